// Given strokes drawn from known primitives (random size, position, rotation, noise, timing),
// when recognized, then each class is recognized with high accuracy; regularized circles are exact.
#include "fit_checks.h"
#include "solvers/stroke/quad_shapes.h"
#include "solvers/stroke/shape_recognizer.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

namespace sculptline::stroketest {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kTrialsPerClass = 20;
// Required share of correctly classified strokes per class.
constexpr double kMinAccuracy = 0.9;

Vec3 rot(const Vec3& p, double a) { return Vec3(std::cos(a) * p.x() - std::sin(a) * p.y(), std::sin(a) * p.x() + std::cos(a) * p.y(), 0); }

Shape makeShape(ShapeKind kind, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0, 1);
    const double size = 60 + 140 * u(rng), angle = 2 * kPi * u(rng);
    const Vec3 c(400 * u(rng) - 200, 400 * u(rng) - 200, 0);
    auto poly = [&](std::vector<Vec3> v, double a) {
        for (auto& p : v) p = c + rot(p, a);
        return polygonShape(v, true);
    };
    switch (kind) {
    case ShapeKind::Line: return lineShape(c, c + rot(Vec3(size, 0, 0), angle));
    case ShapeKind::Arc: {
        const double a0 = angle, span = (0.3 + 0.5 * u(rng)) * 2 * kPi;
        return arcShape(c, size / 2, a0, a0 + span);
    }
    case ShapeKind::Circle: return circleShape(c, size / 2, angle);
    case ShapeKind::Ellipse: return ellipseShape(c, size / 2, size / 2 * (0.4 + 0.3 * u(rng)), angle);
    case ShapeKind::Triangle:
        return poly({{0, 0, 0}, {size, 0, 0}, {size * (0.2 + 0.6 * u(rng)), size * (0.6 + 0.4 * u(rng)), 0}}, angle);
    case ShapeKind::Rectangle: {
        const double h = size * (0.35 + 0.3 * u(rng));
        return poly({{0, 0, 0}, {size, 0, 0}, {size, h, 0}, {0, h, 0}}, 0.25 * (u(rng) - 0.5));
    }
    case ShapeKind::Square: return poly({{0, 0, 0}, {size, 0, 0}, {size, size, 0}, {0, size, 0}}, 0.25 * (u(rng) - 0.5));
    case ShapeKind::Diamond: {
        const double w = size * (0.5 + 0.25 * u(rng));
        return poly({{0, -size / 2, 0}, {w / 2, 0, 0}, {0, size / 2, 0}, {-w / 2, 0, 0}}, 0.2 * (u(rng) - 0.5));
    }
    case ShapeKind::Polyline: {
        Shape s = polygonShape({{0, 0, 0}, {size * 0.4, size * 0.6, 0}, {size * 0.8, 0, 0}, {size * 1.2, size * 0.6, 0}}, false);
        for (auto& p : s.reference) p = c + rot(p, angle);
        return s;
    }
    case ShapeKind::Freeform: {
        Shape s = sCurveShape(size * 1.5);
        for (auto& p : s.reference) p = c + rot(p, angle);
        return s;
    }
    }
    return lineShape(c, c + Vec3(1, 0, 0));
}

TEST(ShapeRecognition, GivenDrawnPrimitives_WhenRecognized_ThenEachClassIsAccurate)
{
    const std::vector<ShapeKind> kinds = {ShapeKind::Line,     ShapeKind::Arc,       ShapeKind::Circle,
                                          ShapeKind::Ellipse,  ShapeKind::Triangle,  ShapeKind::Rectangle,
                                          ShapeKind::Square,   ShapeKind::Diamond,   ShapeKind::Polyline,
                                          ShapeKind::Freeform};
    std::mt19937 rng(2024);
    for (ShapeKind kind : kinds) {
        std::map<std::string, int> got;
        int correct = 0;
        for (int t = 0; t < kTrialsPerClass; ++t) {
            DrawOptions d;
            d.noise = 0.25;
            d.seed = static_cast<unsigned>(rng());
            d.closureOffset = std::uniform_real_distribution<double>(-0.02, 0.04)(rng);
            const Recognition r = recognizeShape(fitStroke(draw(makeShape(kind, rng), d)));
            ++got[shapeName(r.kind)];
            correct += r.kind == kind;
        }
        std::string summary;
        for (const auto& [name, n] : got) summary += name + "=" + std::to_string(n) + " ";
        std::printf("%-10s accuracy %.2f  (%s)\n", shapeName(kind), double(correct) / kTrialsPerClass, summary.c_str());
        EXPECT_GE(double(correct) / kTrialsPerClass, kMinAccuracy) << shapeName(kind) << ": " << summary;
    }
}

TEST(ShapeRecognition, GivenCircleStroke_WhenRegularized_ThenExactRationalCircle)
{
    DrawOptions d;
    d.noise = 0.25;
    const Recognition r = recognizeShape(fitStroke(draw(circleShape({30, -20, 0}, 70), d)));

    ASSERT_EQ(r.kind, ShapeKind::Circle);
    EXPECT_TRUE(r.regularized.isRational());
    EXPECT_EQ(r.regularized.degree(), 2);
    EXPECT_NEAR(r.circle.radius, 70, 1.0);  // the fitted radius, within the noise
    // Exactness: every point of the regularized curve is at the fitted radius to round-off.
    for (int i = 0; i <= 1000; ++i) {
        const Vec3 p = r.regularized.evaluate(i / 1000.0);
        EXPECT_NEAR((p.head<2>() - r.circle.center).norm(), r.circle.radius, 1e-9 * r.circle.radius);
    }
}

TEST(ShapeRecognition, GivenSquareStroke_WhenRegularized_ThenEqualSidesAndRightAngles)
{
    DrawOptions d;
    d.noise = 0.25;
    const Recognition r =
        recognizeShape(fitStroke(draw(polygonShape({{0, 0, 0}, {100, 3, 0}, {97, 104, 0}, {-2, 99, 0}}, true), d)));

    ASSERT_EQ(r.kind, ShapeKind::Square);
    ASSERT_EQ(r.polygon.size(), 4u);
    const double side = (r.polygon[1] - r.polygon[0]).norm();
    for (int i = 0; i < 4; ++i) {
        const Point2 e0 = r.polygon[(i + 1) % 4] - r.polygon[i], e1 = r.polygon[(i + 2) % 4] - r.polygon[(i + 1) % 4];
        EXPECT_NEAR(e0.norm(), side, 1e-9 * side);
        EXPECT_NEAR(e0.dot(e1), 0.0, 1e-9 * side * side);
    }
}

TEST(ShapeRecognition, GivenASquareishStroke_WhenTheDesignerPicksAnotherCandidate_ThenThatShapeIsRegularized)
{
    // Given a square-ish stroke, recognized as a square with a rectangle among the candidates
    DrawOptions d;
    d.noise = 0.25;
    const FitResult fit = fitStroke(draw(polygonShape({{0, 0, 0}, {100, 3, 0}, {97, 104, 0}, {-2, 99, 0}}, true), d));
    const Recognition r = recognizeShape(fit);
    ASSERT_EQ(r.kind, ShapeKind::Square);
    // When the rectangle (not the best) is picked
    const solvers::Curve3d rectangle = regularizeAs(r, fit, ShapeKind::Rectangle);
    // Then it is a closed degree-1 quadrilateral with right angles (sides as drawn, not forced equal)
    EXPECT_EQ(rectangle.degree(), 1);
    EXPECT_TRUE(rectangle.isClosed());
    ASSERT_GE(rectangle.points().size(), 4u);
    for (int i = 0; i < 4; ++i) {
        const auto& q = rectangle.points();
        const Vec3 e0 = q[(i + 1) % 4] - q[i], e1 = q[(i + 2) % 4] - q[(i + 1) % 4];
        EXPECT_NEAR(e0.dot(e1), 0.0, 1e-9 * e0.norm() * e1.norm()) << i;
    }
    // And the best candidate regularizes as recognizeShape did, freeform gives the fit back
    EXPECT_EQ(regularizeAs(r, fit, ShapeKind::Square).points(), r.regularized.points());
    EXPECT_EQ(regularizeAs(r, fit, ShapeKind::Freeform).points(), fit.curve.points());
    // And a shape that was not a candidate is refused
    EXPECT_THROW(regularizeAs(r, fit, ShapeKind::Arc), std::invalid_argument);
}

TEST(ShapeRecognition, GivenClosedPrimitives_WhenRegularized_ThenClosedCurvesThatWrap)
{
    std::mt19937 rng(7);
    const std::vector<ShapeKind> closedKinds = {ShapeKind::Circle,    ShapeKind::Ellipse, ShapeKind::Triangle,
                                                ShapeKind::Rectangle, ShapeKind::Square,  ShapeKind::Diamond};
    for (ShapeKind kind : closedKinds) {
        DrawOptions d;
        d.noise = 0.25;
        const Recognition r = recognizeShape(fitStroke(draw(makeShape(kind, rng), d)));

        ASSERT_EQ(r.kind, kind) << shapeName(kind);
        EXPECT_TRUE(r.regularized.isClosed()) << shapeName(kind);
        // Periodic: the parameter wraps, and the curve meets itself at the seam.
        const double t0 = r.regularized.domainStart(), t1 = r.regularized.domainEnd();
        const double size = r.geometry.extent;
        EXPECT_LE((r.regularized.evaluate(t0) - r.regularized.evaluate(t1)).norm(), 1e-9 * size) << shapeName(kind);
        const double mid = t0 + 0.3 * (t1 - t0);
        EXPECT_LE((r.regularized.evaluate(mid) - r.regularized.evaluate(mid + (t1 - t0))).norm(), 1e-9 * size) << shapeName(kind);
    }
    // Open primitives stay open.
    for (ShapeKind kind : {ShapeKind::Line, ShapeKind::Arc, ShapeKind::Polyline}) {
        const Recognition r = recognizeShape(fitStroke(draw(makeShape(kind, rng))));
        ASSERT_EQ(r.kind, kind) << shapeName(kind);
        EXPECT_FALSE(r.regularized.isClosed()) << shapeName(kind);
    }
}

// Square vs diamond is orientation-dependent by definition (ShapeKind): a square standing on a
// corner relative to the plane's axes is a diamond. Every other class is rotation invariant, and
// square/diamond are invariant under rotations by multiples of 90 degrees.
TEST(ShapeRecognition, GivenRotatedStrokes_WhenRecognized_ThenSameClassExceptSquareDiamondOffQuarterTurns)
{
    auto rotated = [](const Stroke& s, double a) {
        Stroke out = s;
        for (auto& p : out.points) p = rot(p, a);
        return out;
    };
    std::mt19937 rng(11);
    const std::vector<ShapeKind> kinds = {ShapeKind::Line,      ShapeKind::Arc,    ShapeKind::Circle,   ShapeKind::Ellipse,
                                          ShapeKind::Triangle,  ShapeKind::Rectangle, ShapeKind::Polyline, ShapeKind::Freeform};
    for (ShapeKind kind : kinds) {
        DrawOptions d;
        d.noise = 0.25;
        const Stroke s = draw(makeShape(kind, rng), d);
        ASSERT_EQ(recognizeShape(fitStroke(s)).kind, kind) << shapeName(kind);
        for (double a : {0.37, 1.3, 2.9, 4.4}) {
            EXPECT_EQ(recognizeShape(fitStroke(rotated(s, a))).kind, kind) << shapeName(kind) << " rotated by " << a;
        }
    }
    DrawOptions d;
    d.noise = 0.25;
    const Stroke square = draw(polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true), d);
    const Stroke rhombus = draw(polygonShape({{0, -60, 0}, {35, 0, 0}, {0, 60, 0}, {-35, 0, 0}}, true), d);
    for (int quarter = 0; quarter < 4; ++quarter) {
        const double a = quarter * kPi / 2;
        EXPECT_EQ(recognizeShape(fitStroke(rotated(square, a))).kind, ShapeKind::Square) << quarter << " quarter turns";
        // On a corner: the same square, turned by 45 degrees, is a diamond.
        EXPECT_EQ(recognizeShape(fitStroke(rotated(square, a + kPi / 4))).kind, ShapeKind::Diamond) << quarter;
        // A rhombus that is not right-angled is a diamond at any orientation.
        for (double off : {0.0, 0.4, kPi / 4}) {
            EXPECT_EQ(recognizeShape(fitStroke(rotated(rhombus, a + off))).kind, ShapeKind::Diamond) << quarter << " + " << off;
        }
    }
}

TEST(ShapeRecognition, GivenDeclinedRegularization_ThenFittedCurveReturned)
{
    RecognizeOptions o;
    o.regularize = false;
    const FitResult f = fitStroke(draw(circleShape({0, 0, 0}, 50)));
    const Recognition r = recognizeShape(f, o);
    EXPECT_EQ(r.kind, ShapeKind::Circle);
    EXPECT_EQ(r.regularized.pointCount(), f.curve.pointCount());
    EXPECT_FALSE(r.regularized.isRational());
}

}  // namespace
}  // namespace sculptline::stroketest

namespace sculptline::stroketest {
namespace {

// A pen path along the polyline `corners`, a sample every `step`, 10 ms apart.
solvers::stroke::Stroke penAlong(const std::vector<Vec3>& corners, double step)
{
    solvers::stroke::Stroke s;
    for (size_t i = 0; i + 1 < corners.size(); ++i) {
        const Vec3 d = corners[i + 1] - corners[i];
        const int n = std::max(1, static_cast<int>(std::ceil(d.norm() / step)));
        for (int k = 0; k < n; ++k) s.points.push_back(corners[i] + d * (double(k) / n));
    }
    s.points.push_back(corners.back());
    for (size_t i = 0; i < s.points.size(); ++i) s.times.push_back(0.01 * double(i));
    return s;
}

// The $1 delete mark with short tails: down-right, up, down-left across the first leg. Its ends lie
// 0.28 from the crossing, so the conditioning closes the loop there and trims 19 % of the length,
// under RecognizeOptions::maxOvershoot (25 %): only the crossing rule (crossingTail) reopens it.
const std::vector<Vec3> kShortDeleteMark = {{30, 70, 0}, {100, 0, 0}, {100, 100, 0}, {30, 30, 0}};
constexpr double kPenStep = 1.0;  // plane units between samples; the mark is 100 units wide

TEST(ShapeRecognition, GivenAStrokeCrossingItselfWithBothEndsOut_WhenRecognized_ThenAnOpenPolylineNotATriangle)
{
    const solvers::stroke::Stroke mark = penAlong(kShortDeleteMark, kPenStep);

    const auto withRule = solvers::stroke::recognizeStroke(mark);
    solvers::stroke::RecognizeOptions off;
    off.crossingTail = 0.0;
    const auto withoutRule = solvers::stroke::recognizeStroke(mark, {}, off);

    EXPECT_FALSE(withRule.recognition.geometry.closed);
    EXPECT_EQ(withRule.recognition.kind, ShapeKind::Polyline);
    // The stroke does exercise the rule: without it the loop at the crossing is a triangle.
    EXPECT_TRUE(withoutRule.recognition.geometry.closed);
    EXPECT_EQ(withoutRule.recognition.kind, ShapeKind::Triangle);
}

TEST(ShapeRecognition, GivenASquareOvershotAlongItsFirstSide_WhenRecognized_ThenStillAClosedSquare)
{
    // Started a little before the first corner (the start sticks out) and drawn on past it along the
    // first side (the end runs on the loop): a closed square.
    const solvers::stroke::Stroke square = penAlong({{-10, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}, {0, 0, 0}, {0, 0, 0}, {15, 0, 0}}, kPenStep);

    const auto r = solvers::stroke::recognizeStroke(square);

    EXPECT_TRUE(r.recognition.geometry.closed);
    EXPECT_EQ(r.recognition.kind, ShapeKind::Square);
}

// RecognizeOptions::looseQuad: a rectangle drawn askew (sheared into a parallelogram, or tapered as
// in perspective) strays from right angles by more than rightAngle, and the regular rectangle
// misses it by a large share of the residual scale; it is still read as a rectangle by its own
// quad, and without the rule it is a polyline.
TEST(ShapeRecognition, GivenASkewedOrTaperedRectangle_WhenRecognizedWithLooseQuad_ThenARectangleAndWithoutItNot)
{
    const std::vector<std::pair<const char*, std::vector<Vec3>>> drawn = {
        // sheared by 0.5: angles 63 and 117 degrees, sides 160 and 101
        {"sheared", {{0, 0, 0}, {160, 0, 0}, {205, 90, 0}, {45, 90, 0}}},
        // tapered: the top edge 80, the bottom 160, angles 66 and 114 degrees
        {"tapered", {{0, 0, 0}, {160, 0, 0}, {120, 90, 0}, {40, 90, 0}}},
    };
    RecognizeOptions off;
    off.looseQuad = 0.0;
    for (const auto& [name, corners] : drawn) {
        for (double a : {0.0, 0.7}) {
            std::vector<Vec3> v = corners;
            for (auto& p : v) p = rot(p, a);
            DrawOptions d;
            d.noise = 0.25;
            const FitResult fit = fitStroke(draw(polygonShape(v, true), d));
            const Recognition with = recognizeShape(fit);
            const Recognition without = recognizeShape(fit, off);
            auto describe = [](const Recognition& r) {
                std::string s;
                for (const auto& c : r.candidates)
                    s += std::string(shapeName(c.kind)) + ":" + std::to_string(c.score) + " ";
                return s;
            };
            EXPECT_EQ(with.kind, ShapeKind::Rectangle) << name << " rotated " << a << ": " << describe(with);
            EXPECT_NE(without.kind, ShapeKind::Rectangle) << name << " rotated " << a << ": " << describe(without);
            // Regularized as the regular rectangle: right angles.
            if (with.kind == ShapeKind::Rectangle) {
                ASSERT_EQ(with.polygon.size(), 4u);
                for (int i = 0; i < 4; ++i) {
                    const Point2 e0 = with.polygon[(i + 1) % 4] - with.polygon[i],
                                 e1 = with.polygon[(i + 2) % 4] - with.polygon[(i + 1) % 4];
                    EXPECT_NEAR(e0.dot(e1), 0.0, 1e-9 * e0.norm() * e1.norm()) << name;
                }
            }
        }
    }
}

}  // namespace
}  // namespace sculptline::stroketest

namespace sculptline::stroketest {
namespace {

// An arrow drawn in one stroke whose head's last line runs back toward the shaft's start (the
// vertices of a development arrow, s03 slow 1 sheared by 0.3, in units of 200): it turns by more
// than nearLoopTurn around its circle's centre and ends heading for its start, so recognizeStroke
// fits it again closed. Closed it reads as nothing (freeform); the closing is a guess that must
// explain the stroke, so the open polyline it was stays.
TEST(ShapeRecognition, GivenAnArrowWhoseHeadPointsBackToItsStart_WhenRecognized_ThenTheOpenPolylineStays)
{
    const solvers::stroke::Stroke arrow =
        penAlong({{0, 0, 0}, {128, 70, 0}, {74, 60, 0}, {136, 68, 0}, {84, 7, 0}}, kPenStep);

    const auto r = solvers::stroke::recognizeStroke(arrow);
    // The closed reading the rule declines: the same stroke fitted closed.
    solvers::stroke::FitOptions closed;
    closed.conditioning.closure = solvers::stroke::Closure::Closed;
    const auto loop = solvers::stroke::recognizeShape(solvers::stroke::fitStroke(arrow, closed));

    EXPECT_FALSE(r.recognition.geometry.closed);
    EXPECT_EQ(r.recognition.kind, ShapeKind::Polyline);
    EXPECT_EQ(r.recognition.geometry.vertices.size(), 5u);
    EXPECT_EQ(loop.kind, ShapeKind::Freeform);
}

}  // namespace
}  // namespace sculptline::stroketest

namespace sculptline::stroketest {
namespace {

// A loop with straight sides and round corners, as a hand drawing fast makes it: the convex polygon
// `inner` (counter-clockwise) grown by `radius` (its corners arcs of that radius about the
// vertices), begun halfway along its first side. No corner: the corner detector sees none.
Shape roundedPolygon(const std::vector<Vec3>& inner, double radius)
{
    Shape s;
    s.closed = true;
    const size_t m = inner.size();
    const auto outward = [&](size_t i) {  // the outward normal of side i (inner[i] -> inner[i+1])
        const Vec3 e = (inner[(i + 1) % m] - inner[i]).normalized();
        return Vec3(e.y(), -e.x(), 0);
    };
    constexpr int kPerArc = 24, kPerSide = 60;
    for (size_t k = 0; k <= m; ++k) {
        const size_t i = k % m;
        const Vec3 a = inner[i] + radius * outward(i), b = inner[(i + 1) % m] + radius * outward(i);
        // Side i from its middle (first pass) or its start (last pass: up to its middle).
        const int from = k == 0 ? kPerSide / 2 : 0, to = k == m ? kPerSide / 2 : kPerSide;
        for (int j = from; j < to; ++j) s.reference.push_back(a + (b - a) * (double(j) / kPerSide));
        if (k == m) break;
        // The arc about the next vertex, from side i's normal to side i+1's.
        const Vec3 n0 = outward(i), n1 = outward((i + 1) % m);
        const double t0 = std::atan2(n0.y(), n0.x());
        double sweep = std::atan2(n1.y(), n1.x()) - t0;
        while (sweep < 0) sweep += 2 * kPi;
        for (int j = 0; j < kPerArc; ++j) {
            const double t = t0 + sweep * j / kPerArc;
            s.reference.push_back(inner[(i + 1) % m] + radius * Vec3(std::cos(t), std::sin(t), 0));
        }
    }
    return s;
}

// A rectangle drawn fast, every corner rounded off and begun halfway along a side, straight or
// sheared: the corner detector finds no corner, so the vertices are the recognizer's own. They are
// sought from the loop's extremes, not from where the hand began (a vertex at the seam made the
// others miss the corners: development rectangles overshot 10 % with corners rounded over 8 % of
// the length, 97 of 150 misread); and the rounded quad lies closer to the stroke than the ellipse,
// so the ellipse does not win (RecognizeOptions::roundedSides).
TEST(ShapeRecognition, GivenARoundedRectangleBegunMidSide_WhenRecognized_ThenARectangleNotAnEllipse)
{
    const std::vector<std::pair<const char*, std::vector<Vec3>>> drawn = {
        {"upright", {{0, 0, 0}, {140, 0, 0}, {140, 70, 0}, {0, 70, 0}}},
        // sheared by 0.5: angles 63 and 117 degrees
        {"sheared", {{0, 0, 0}, {140, 0, 0}, {175, 70, 0}, {35, 70, 0}}},
    };
    // Corners rounded by 20; round corners: the hand does not slow down there.
    const auto drawRounded = [](const std::vector<Vec3>& inner) {
        DrawOptions d;
        d.noise = 0.25;
        d.cornerSlowdown = 1.0;
        return draw(roundedPolygon(inner, 20.0), d);
    };
    for (const auto& [name, inner] : drawn) {
        const StrokeRecognition r = recognizeStroke(drawRounded(inner));
        std::string seen;
        for (const auto& c : r.recognition.candidates)
            seen += std::string(shapeName(c.kind)) + ":" + std::to_string(c.score) + " ";
        EXPECT_LE(r.fit.corners.size(), 1u) << name << ": the corners must be round for this test";
        EXPECT_EQ(r.recognition.kind, ShapeKind::Rectangle) << name << ": " << seen;
    }
    // The rule off, the sheared one is read as an ellipse (0.77 against the rectangle's 0.58): the
    // test sees what the rule does.
    RecognizeOptions off;
    off.roundedSides = 0.0;
    const StrokeRecognition r = recognizeStroke(drawRounded(drawn[1].second), {}, off);
    EXPECT_EQ(r.recognition.kind, ShapeKind::Ellipse);
}

}  // namespace
}  // namespace sculptline::stroketest

namespace sculptline::stroketest {
namespace {

// roundedPolygonResidual (any convex polygon, by its inward offset) against roundedRectangleResidual
// (a rectangle's rounded-box distance, written independently): on an exact rectangle the two are
// the same function of the points; on the outline of a rounded polygon whose radius is among those
// tried the residual is the outline's own discretization; a reflex polygon has none.
TEST(ShapeRecognition,
     GivenRoundedPolygons_WhenTheirResidualIsMeasured_ThenItAgreesWithTheRectangleFormAndVanishesOnTheOutline)
{
    using detail::roundedPolygonResidual;
    using detail::roundedRectangleResidual;
    const double a = 0.4;  // rotated, so that neither form can lean on the axes
    const std::vector<Point2> rect = {
        Point2(0, 0), Point2(120 * std::cos(a), 120 * std::sin(a)),
        Point2(120 * std::cos(a) - 50 * std::sin(a), 120 * std::sin(a) + 50 * std::cos(a)),
        Point2(-50 * std::sin(a), 50 * std::cos(a))};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-40, 160);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<Point2> pts;
        for (int k = 0; k < 30; ++k) pts.emplace_back(u(rng), u(rng));
        EXPECT_NEAR(roundedPolygonResidual(pts, rect, 0.5), roundedRectangleResidual(pts, rect, false, 0.5), 1e-9);
    }
    // A parallelogram sheared by 0.3 (long sides 70 apart) grown by r = 8.75: its outline, sampled
    // exactly on the sides and arcs, lies on the grown polygon rounded by r. That polygon's smallest
    // width is 70 + 2r, so r is the radius tried at 0.2 of its half-width (0.05 steps up to 0.5).
    const double r = 8.75;
    const std::vector<Vec3> inner3 = {{0, 0, 0}, {140, 0, 0}, {161, 70, 0}, {21, 70, 0}};
    const Shape outline = roundedPolygon(inner3, r);
    std::vector<Point2> on, inner, grown;
    for (const auto& p : outline.reference) on.emplace_back(p.x(), p.y());
    for (const auto& p : inner3) inner.emplace_back(p.x(), p.y());
    for (size_t i = 0; i < 4; ++i) {  // each vertex where the sides moved out by r meet
        const Point2 p0 = inner[(i + 3) % 4], p1 = inner[i], p2 = inner[(i + 1) % 4];
        const Point2 e0 = (p1 - p0).normalized(), e1 = (p2 - p1).normalized();
        const Point2 a0 = p1 + r * Point2(e0.y(), -e0.x()), a1 = p1 + r * Point2(e1.y(), -e1.x());
        const double t = ((a1 - a0).x() * e1.y() - (a1 - a0).y() * e1.x()) / (e0.x() * e1.y() - e0.y() * e1.x());
        grown.push_back(a0 + t * e0);
    }
    EXPECT_LT(roundedPolygonResidual(on, grown, 0.5), 1e-6);
    EXPECT_GT(roundedRectangleResidual(on, grown, false, 0.5), 2.0);  // a rectangle cannot follow the shear
    // Not convex: no rounded form.
    const std::vector<Point2> dart = {Point2(0, 0), Point2(100, 0), Point2(50, 20), Point2(50, 100)};
    EXPECT_TRUE(std::isinf(roundedPolygonResidual(on, dart, 0.5)));
}

}  // namespace
}  // namespace sculptline::stroketest
