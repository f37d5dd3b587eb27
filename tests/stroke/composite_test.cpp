// Given pairs of strokes drawn one after the other, when related and composed, then the relations
// and Fig. 3-4 composite objects come out, and the Table 3-2 user model matches and learns.
#include "solvers/stroke/user_model.h"
#include "fit_checks.h"

#include <gtest/gtest.h>

namespace sculptline::stroketest {
namespace {

Recognition rec(const Shape& s, unsigned seed = 1)
{
    DrawOptions d;
    d.noise = 0.25;
    d.seed = seed;
    return recognizeShape(fitStroke(draw(s, d)));
}

bool has(const std::vector<Relation>& r, Relation x) { return std::find(r.begin(), r.end(), x) != r.end(); }

TEST(Relations, GivenLinePairs_ThenParallelPerpendicularTouchingOverlappingDisjoint)
{
    const Recognition base = rec(lineShape({0, 0, 0}, {100, 0, 0}));
    ASSERT_EQ(base.kind, ShapeKind::Line);

    const auto parallel = relate(base, rec(lineShape({0, 40, 0}, {100, 42, 0})));
    const auto corner = relate(base, rec(lineShape({100, 1, 0}, {100, 80, 0})));
    const auto crossing = relate(base, rec(lineShape({50, -40, 0}, {52, 40, 0})));

    EXPECT_TRUE(has(parallel, Relation::Parallel));
    EXPECT_TRUE(has(parallel, Relation::Disjoint));
    EXPECT_TRUE(has(corner, Relation::Perpendicular));
    EXPECT_TRUE(has(corner, Relation::Touching));
    EXPECT_TRUE(has(crossing, Relation::Perpendicular));
    EXPECT_TRUE(has(crossing, Relation::Overlapping));
}

TEST(Relations, GivenNestedAndSeparateCircles_ThenInsideAndDisjoint)
{
    const Recognition big = rec(circleShape({0, 0, 0}, 100));
    EXPECT_EQ(relate(big, rec(circleShape({10, 5, 0}, 30))), std::vector<Relation>{Relation::Inside});
    EXPECT_EQ(relate(big, rec(circleShape({300, 0, 0}, 30))), std::vector<Relation>{Relation::Disjoint});
}

TEST(Composite, GivenFigure34Pairs_ThenPrismCylinderConeExtrusionSkinning)
{
    const Recognition circle = rec(circleShape({0, 0, 0}, 60));
    const Recognition triangle = rec(polygonShape({{0, 0, 0}, {120, 0, 0}, {60, 100, 0}}, true));
    const Recognition square = rec(polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true));
    ASSERT_EQ(circle.kind, ShapeKind::Circle);
    ASSERT_EQ(triangle.kind, ShapeKind::Triangle);
    ASSERT_EQ(square.kind, ShapeKind::Square);

    auto compose = [](const Recognition& a, const Recognition& b) { return composeShapes(a, b, relate(a, b)); };
    EXPECT_EQ(compose(circle, rec(lineShape({60, 0, 0}, {60, 150, 0}))), CompositeKind::Cylinder);
    EXPECT_EQ(compose(circle, rec(lineShape({0, 0, 0}, {0, 150, 0}))), CompositeKind::Cone);
    EXPECT_EQ(compose(triangle, rec(lineShape({-20, 30, 0}, {140, 35, 0}))), CompositeKind::Prism);
    EXPECT_EQ(compose(square, rec(lineShape({100, 100, 0}, {160, 160, 0}))), CompositeKind::Extrusion);
    EXPECT_EQ(compose(rec(sCurveShape(200)), rec(sCurveShape(200), 2)), CompositeKind::None);  // the same place: crossing
    Shape lifted = sCurveShape(200);
    for (auto& p : lifted.reference) p.y() += 150;
    EXPECT_EQ(compose(rec(sCurveShape(200)), rec(lifted)), CompositeKind::Skinning);
}

// Fig. 3-4 (d): a square profile, an edge rising from its corner, and the top face where the edge
// carries the profile (or a second, parallel edge) make a polygon volume.
struct VolumeStrokes {
    Shape profile = polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true);
    Shape edge = lineShape({100, 100, 0}, {160, 160, 0});
    Shape top = polygonShape({{60, 60, 0}, {160, 60, 0}, {160, 160, 0}, {60, 160, 0}}, true);
    Shape secondEdge = lineShape({100, 0, 0}, {160, 60, 0});
};

TEST(Composite, GivenProfileEdgeAndTopFace_ThenPolygonVolume)
{
    const VolumeStrokes v;
    const Recognition profile = rec(v.profile), edge = rec(v.edge);
    ASSERT_EQ(profile.kind, ShapeKind::Square);
    ASSERT_EQ(edge.kind, ShapeKind::Line);
    ASSERT_EQ(composeShapes(profile, edge, relate(profile, edge)), CompositeKind::Extrusion);

    EXPECT_EQ(composeThree(profile, edge, rec(v.top)), CompositeKind::PolygonVolume);
    EXPECT_EQ(composeThree(profile, edge, rec(v.secondEdge)), CompositeKind::PolygonVolume);
    // A triangle profile with its top triangle: the same construction for any polygon.
    const Shape tri = polygonShape({{0, 0, 0}, {120, 0, 0}, {60, 100, 0}}, true);
    const Shape triTop = polygonShape({{50, 40, 0}, {170, 40, 0}, {110, 140, 0}}, true);
    EXPECT_EQ(composeThree(rec(tri), rec(lineShape({120, 0, 0}, {170, 40, 0})), rec(triTop)), CompositeKind::PolygonVolume);
}

TEST(Composite, GivenThirdStrokesThatBreakTheConstraints_ThenNoPolygonVolume)
{
    const VolumeStrokes v;
    const Recognition profile = rec(v.profile), edge = rec(v.edge);
    // Top face in the wrong place (not where the edge carries the profile).
    EXPECT_EQ(composeThree(profile, edge, rec(polygonShape({{200, -150, 0}, {300, -150, 0}, {300, -50, 0}, {200, -50, 0}}, true))),
              CompositeKind::None);
    // Wrong size: half the profile.
    EXPECT_EQ(composeThree(profile, edge, rec(polygonShape({{85, 85, 0}, {135, 85, 0}, {135, 135, 0}, {85, 135, 0}}, true))),
              CompositeKind::None);
    // Another kind of shape: a circle at the top face's place.
    EXPECT_EQ(composeThree(profile, edge, rec(circleShape({110, 110, 0}, 50))), CompositeKind::None);
    // A line that is not parallel to the edge.
    EXPECT_EQ(composeThree(profile, edge, rec(lineShape({100, 0, 0}, {100, -80, 0}))), CompositeKind::None);
    // The first two strokes are no extrusion (the line misses the profile).
    EXPECT_EQ(composeThree(profile, rec(lineShape({200, 200, 0}, {260, 260, 0})), rec(v.top)), CompositeKind::None);
}

TEST(UserModel, GivenThreeStrokeVolume_ThenChainRowMatchedWithTheExtrusionAsPreNode)
{
    UserModel m = UserModel::predefined();
    const size_t before = m.nodes().size();
    const VolumeStrokes v;
    DrawOptions d;
    d.noise = 0.25;
    const std::vector<FitResult> fits = {fitStroke(draw(v.profile, d)), fitStroke(draw(v.edge, d)), fitStroke(draw(v.top, d))};

    const auto seq = interpretStrokes(fits, m);

    ASSERT_EQ(seq.size(), 3u);
    EXPECT_EQ(seq[1].composite, CompositeKind::Extrusion);
    EXPECT_EQ(m.nodes()[seq[1].compositeNode - 1].name, "extrusion");
    EXPECT_EQ(seq[2].composite, CompositeKind::PolygonVolume);
    EXPECT_EQ(seq[2].preNode, seq[1].compositeNode);  // Table 3-2 chain: P->Pre-Node = Q
    EXPECT_EQ(m.nodes()[seq[2].compositeNode - 1].name, "polygon_volume");
    EXPECT_FALSE(seq[2].learned);
    EXPECT_EQ(m.nodes().size(), before);

    // A triangle volume is not predefined: learned once as a chain row, then matched.
    const Shape tri = polygonShape({{0, 0, 0}, {120, 0, 0}, {60, 100, 0}}, true);
    const std::vector<FitResult> triFits = {fitStroke(draw(tri, d)), fitStroke(draw(lineShape({120, 0, 0}, {170, 40, 0}), d)),
                                            fitStroke(draw(polygonShape({{50, 40, 0}, {170, 40, 0}, {110, 140, 0}}, true), d))};
    const auto first = interpretStrokes(triFits, m);
    const size_t learnedSize = m.nodes().size();
    const auto again = interpretStrokes(triFits, m);
    EXPECT_EQ(first[2].composite, CompositeKind::PolygonVolume);
    EXPECT_TRUE(first[2].learned);
    EXPECT_EQ(m.nodes()[first[2].compositeNode - 1].preNode, first[1].compositeNode);
    EXPECT_FALSE(again[2].learned);
    EXPECT_EQ(again[2].compositeNode, first[2].compositeNode);
    EXPECT_EQ(m.nodes().size(), learnedSize);
}

TEST(UserModel, GivenTable32_ThenMatchAndCandidatesAsInTheThesis)
{
    const UserModel m = UserModel::predefined("alice");
    EXPECT_EQ(m.match(2, 3, "C7"), 8);
    EXPECT_EQ(m.match(3, 4, "C8"), 7);
    EXPECT_EQ(m.match(4, 3, "C8"), 0);
    // Thesis §3.1.3: after T2, the rows with pre-node 2 (T8, T9, T11) are offered.
    EXPECT_EQ(m.candidatesAfter(2), (std::vector<int>{8, 9, 11}));
    EXPECT_EQ(m.primitiveNode(ShapeKind::Circle), 1);
    EXPECT_EQ(m.primitiveNode(ShapeKind::Ellipse), 0);
}

TEST(UserModel, GivenStrokeSequences_ThenKnownPairsMatchAndNewPairsAreLearnedOnce)
{
    UserModel m = UserModel::predefined();
    const size_t before = m.nodes().size();
    DrawOptions d;
    d.noise = 0.25;
    const FitResult triangle = fitStroke(draw(polygonShape({{0, 0, 0}, {120, 0, 0}, {60, 100, 0}}, true), d));
    const FitResult line = fitStroke(draw(lineShape({-20, 30, 0}, {140, 35, 0}), d));
    const FitResult square = fitStroke(draw(polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true), d));
    const FitResult small = fitStroke(draw(circleShape({50, 50, 0}, 20), d));

    const auto prism = interpretStrokes({triangle, line}, m);
    ASSERT_EQ(prism.size(), 2u);
    EXPECT_EQ(prism[1].composite, CompositeKind::Prism);
    EXPECT_EQ(prism[1].compositeNode, 8);
    EXPECT_FALSE(prism[1].learned);
    EXPECT_EQ(m.nodes().size(), before);

    const auto first = interpretStrokes({square, small}, m);  // circle inside square: not in Table 3-2
    EXPECT_TRUE(first[1].learned);
    EXPECT_EQ(m.nodes().size(), before + 1);
    EXPECT_EQ(m.nodes().back().constraint, "C11");
    const auto again = interpretStrokes({square, small}, m);
    EXPECT_FALSE(again[1].learned);
    EXPECT_EQ(again[1].compositeNode, first[1].compositeNode);
    EXPECT_EQ(m.nodes().size(), before + 1);
}

}  // namespace
}  // namespace sculptline::stroketest
