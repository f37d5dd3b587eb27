// Given strokes synthesized from known curves, when fitted, then the curve stays within tolerance.
#include "solvers/bspline/projection.h"
#include "solvers/stroke/stroke_fitter.h"
#include "fit_checks.h"

#include <gtest/gtest.h>

namespace sculptline::stroketest {
namespace {

using namespace solvers::stroke;

TEST(StrokeFit, SmokeShapes)
{
    const std::vector<std::pair<const char*, Shape>> shapes = {
        {"line", lineShape({0, 0, 0}, {200, 50, 0})},
        {"arc", arcShape({0, 0, 0}, 100, 0.2, 2.5)},
        {"circle", circleShape({10, 20, 0}, 80)},
        {"ellipse", ellipseShape({0, 0, 0}, 120, 60, 0.3)},
        {"square", polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true)},
        {"zigzag", polygonShape({{0, 0, 0}, {60, 80, 0}, {120, 0, 0}, {180, 80, 0}}, false)},
        {"s", sCurveShape(200)},
        {"spiral", spiralShape(100, 2.5)},
    };
    for (const auto& [name, shape] : shapes) {
        DrawOptions d;
        d.noise = 0.2;
        const Stroke s = draw(shape, d);
        const FitResult r = fitStroke(s);
        const double dev = maxDeviation(r.curve, r.conditioned.points);
        std::printf("%-8s raw=%zu cond=%d samples=%zu ctrl=%d corners=%zu closed=%d maxErr=%.3f tol=%.3f dev=%.3f\n",
                    name, s.points.size(), r.conditioned.size(), r.samples.size(), r.curve.pointCount() - (r.curve.isClosed() ? 3 : 0),
                    r.corners.size(), r.curve.isClosed(), r.maxError, r.tolerance, dev);
        EXPECT_TRUE(r.converged) << name;
        EXPECT_LE(dev, r.tolerance * 1.0001) << name;
    }
}

}  // namespace
}  // namespace sculptline::stroketest
