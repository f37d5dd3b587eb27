// Given strokes drawn from known primitives (random size, position, rotation, noise, timing),
// when recognized, then each class is recognized with high accuracy; regularized circles are exact.
#include "solvers/stroke/shape_recognizer.h"
#include "fit_checks.h"

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
