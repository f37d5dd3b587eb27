// Loft: sections met to 1e-9, builder re-solves match a fresh build, degenerate input refused.
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/loft.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

// Boat-like sections: a quadratic and cubics with different knots at increasing x.
std::vector<Curve3d> hullSections()
{
    std::vector<Curve3d> s;
    s.push_back(Curve3d(2, {0, 0, 0, 1, 1, 1}, {{0, -1, 1}, {0, 0, -0.5}, {0, 1, 1}}));
    s.push_back(cubic({{2, -2, 1}, {2, -1.5, -1}, {2, 0, -1.2}, {2, 1.5, -1}, {2, 2, 1}}));
    s.push_back(cubic({{4, -2.2, 1}, {4, -1.8, -1.1}, {4, 1.8, -1.1}, {4, 2.2, 1}}));
    s.push_back(cubic({{7, -1, 1}, {7, -0.8, 0}, {7, -0.2, -0.5}, {7, 0.2, -0.5}, {7, 0.8, 0}, {7, 1, 1}}));
    return s;
}

}  // namespace

TEST(Loft, GivenFourSections_WhenLofted_ThenEachSectionIsAnIsoCurve)
{
    const std::vector<Curve3d> sections = hullSections();
    LoftBuilder builder(sections);
    const Surface3d& s = builder.surface();
    const std::vector<double>& v = builder.crossParameters();
    ASSERT_EQ(v.size(), sections.size());
    for (size_t k = 0; k < sections.size(); ++k) EXPECT_LT(isoDeviation(s, true, v[k], sections[k]), kExact) << k;
    EXPECT_EQ(s.degreeV(), 3);
    EXPECT_GT(minNeighbourNormalDot(s), 0.0);
}

TEST(Loft, GivenTwoSections_WhenLofted_ThenRuledSurface)
{
    const std::vector<Curve3d> sections{cubic({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}}),
                                        cubic({{0, 0, 2}, {1, -1, 2}, {2, 0, 2}, {3, -1, 2}})};
    const Surface3d s = loft(sections);
    EXPECT_EQ(s.degreeV(), 1);
    EXPECT_LT(isoDeviation(s, true, 0.0, sections[0]), kExact);
    EXPECT_LT(isoDeviation(s, true, 1.0, sections[1]), kExact);
    // Ruled: the midpoint of corresponding points lies on the surface at v = 1/2.
    const Vec3 mid = 0.5 * (sections[0].evaluate(0.3) + sections[1].evaluate(0.3));
    EXPECT_LT((s.evaluate(0.3, 0.5) - mid).norm(), kExact);
}

TEST(Loft, GivenRationalCircles_WhenLofted_ThenCirclesMetExactly)
{
    const double w = std::sqrt(0.5);
    auto circle = [&](double z, double r) {
        return Curve3d(2, {0, 0, 0, 1, 1, 1}, {{r, 0, z}, {r, r, z}, {0, r, z}}, {1, w, 1});
    };
    const std::vector<Curve3d> sections{circle(0, 1), circle(1, 2), circle(2, 1.5)};
    LoftBuilder b(sections);
    for (size_t k = 0; k < sections.size(); ++k)
        EXPECT_LT(isoDeviation(b.surface(), true, b.crossParameters()[k], sections[k]), kExact);
    EXPECT_TRUE(b.surface().isRational());
}

TEST(Loft, GivenBuilder_WhenOneSectionMoves_ThenUpdateMatchesSectionAndKeepsParameters)
{
    std::vector<Curve3d> sections = hullSections();
    LoftBuilder builder(sections);
    const std::vector<double> v = builder.crossParameters();
    std::vector<Vec3> pts = sections[2].points();
    pts[1] += Vec3(0.3, -0.2, 0.4);
    const Curve3d moved(sections[2].degree(), sections[2].knots(), pts);
    const Surface3d& s = builder.update(2, moved);
    EXPECT_EQ(builder.crossParameters(), v);
    EXPECT_LT(isoDeviation(s, true, v[2], moved), kExact);
    EXPECT_LT(isoDeviation(s, true, v[0], sections[0]), kExact);
}

TEST(Loft, GivenBuilder_WhenSectionGetsNewKnots_ThenFullRebuildStillExact)
{
    std::vector<Curve3d> sections = hullSections();
    LoftBuilder builder(sections);
    const Curve3d refined = sections[1].insertKnot(0.37);
    const Curve3d other = cubic({{2, -2, 1}, {2, -1, -1.5}, {2, 0, -2}, {2, 0.5, -1.5}, {2, 1.5, -1}, {2, 2, 1}, {2, 2.1, 1.5}});
    const Surface3d& s = builder.update(1, other);
    EXPECT_LT(isoDeviation(s, true, builder.crossParameters()[1], other), kExact);
    const Surface3d& again = builder.update(1, refined);
    EXPECT_LT(isoDeviation(again, true, builder.crossParameters()[1], sections[1]), kExact);
}

TEST(Loft, GivenSectionDrawnBackwards_WhenLofted_ThenSameSurfaceAndBuilderKeepsTheTurn)
{
    std::vector<Curve3d> sections = hullSections();
    const LoftBuilder forward(sections);
    sections[2] = reversedCurve(normalizedCurve(sections[2]));
    LoftBuilder builder(sections);
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j)
            EXPECT_LT((builder.surface().evaluate(i / 10.0, j / 10.0) - forward.surface().evaluate(i / 10.0, j / 10.0)).norm(),
                      kExact);
    // A drag of the reversed section arrives in its own (reversed) direction and stays met.
    std::vector<Vec3> pts = sections[2].points();
    pts[1] += Vec3(0.2, 0.1, -0.3);
    const Curve3d moved(sections[2].degree(), sections[2].knots(), pts);
    EXPECT_LT(isoDeviation(builder.update(2, moved), true, builder.crossParameters()[2], moved, true), kExact);
}

TEST(Loft, GivenOneSection_WhenLofted_ThenClearError)
{
    try {
        loft({cubic({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}})});
        FAIL() << "expected GeometryError";
    } catch (const GeometryError& e) {
        EXPECT_NE(std::string(e.what()).find("at least two sections"), std::string::npos) << e.what();
    }
}

TEST(Loft, GivenRepeatedSection_WhenLofted_ThenClearError)
{
    const Curve3d c = cubic({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}});
    const Curve3d d = cubic({{0, 0, 1}, {1, 1, 1}, {2, 0, 1}, {3, 1, 1}});
    EXPECT_THROW(loft({c, d, d}), GeometryError);
}
