#include "solvers/surfaces/boundary_rotation.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/knot_algorithms.h"
#include "solvers/geometry/plane_fit.h"
#include "solvers/surfaces/approximation_tolerance.h"
#include "solvers/surfaces/compatible_curves.h"
#include "solvers/surfaces/interpolation.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace sculptline::solvers::surfaces {

namespace {

using Vec3 = Eigen::Vector3d;

// Dense samples per knot span for plane fitting and deviation measurement.
constexpr int kSamplesPerSpan = 16;
// Ratio of the two largest principal extents below which the samples lie on a line.
constexpr double kCollinearRatio = 1e-9;
// Margin on the estimate of the pieces a span needs, so that one more pass is rarely needed; and a
// bound on them per pass (the estimate is for smooth E; near a vanishing D it is not).
constexpr double kGrowthMargin = 1.25;
constexpr int kMaxPiecesPerPass = 8;

// D turned by 90 degrees towards n within span(D, n), same length (zero when D vanishes).
Vec3 quarterTurn(const Vec3& d, const Vec3& n)
{
    const double len = d.norm();
    if (!(len > 0.0)) return Vec3::Zero();
    const Vec3 e = n - n.dot(d / len) * (d / len);
    return e.norm() > 0.0 ? Vec3(len * e.normalized()) : Vec3::Zero();
}

std::vector<double> samples(const KnotVector& knots, int degree)
{
    std::vector<double> u{0.0};
    std::vector<double> br{0.0};
    for (double k : interiorBreakpoints(degree, knots)) br.push_back(k);
    br.push_back(1.0);
    for (size_t s = 0; s + 1 < br.size(); ++s)
        for (int k = 1; k <= kSamplesPerSpan; ++k) u.push_back(br[s] + (br[s + 1] - br[s]) * k / kSamplesPerSpan);
    return u;
}

}  // namespace

Vec3 bestFitPlaneNormal(const std::vector<Curve3d>& curves)
{
    std::vector<Vec3> pts;
    for (const Curve3d& c0 : curves) {
        const Curve3d c = normalizedCurve(c0);
        for (double u : samples(c.knots(), c.degree())) pts.push_back(c.evaluate(u));
    }
    const PlaneFit plane = bestFitPlane(pts);
    if (!(plane.spread(1) > kCollinearRatio * kCollinearRatio * plane.spread(2)))
        throw GeometryError("curves: the outlines lie on one line; they define no plane to rotate out of");
    return plane.normal;
}

Vec3 boundaryRotationPoint(const Curve3d& left, const Curve3d& right, const Vec3& n, double u, double theta)
{
    const Vec3 l = left.evaluate(u);
    const Vec3 r = right.evaluate(u);
    const Vec3 q = 0.5 * (l + r);
    const Vec3 d = 0.5 * (l - r);
    return q + std::cos(theta) * d + std::sin(theta) * quarterTurn(d, n);
}

ApproximatedSurface boundaryRotation(const Curve3d& left, const Curve3d& right, const ApproximationOptions& options)
{
    if (left.isRational() || right.isRational())
        throw GeometryError("curves: rational outlines are not supported by boundary-based rotation");
    // Outlines drawn in opposite directions are paired end to end the way that matches closer ends.
    const Curve3d l = normalizedCurve(left);
    Curve3d r = normalizedCurve(right);
    const auto gap = [&](const Curve3d& a, const Curve3d& b) {
        return (a.evaluate(0.0) - b.evaluate(0.0)).norm() + (a.evaluate(1.0) - b.evaluate(1.0)).norm();
    };
    if (gap(l, reversedCurve(r)) < gap(l, r)) r = reversedCurve(r);
    const std::vector<Curve3d> c = makeCompatible({l, r});
    const Vec3 n = bestFitPlaneNormal(c);
    const double size = std::max(c[0].controlSize(), c[1].controlSize());
    const double tolerance =
        approximationTolerance(options.tolerance, kDefaultApproximationRelative * size, coordinateScale({&c[0], &c[1]}));

    const int p = c[0].degree();
    KnotVector knots = c[0].knots();
    // Rows: Q (3 columns) and D (3 columns) side by side, refined together (exact).
    ControlMatrix qd(c[0].pointCount(), 6);
    for (int i = 0; i < c[0].pointCount(); ++i) {
        qd.block(i, 0, 1, 3) = 0.5 * (c[0].points()[i] + c[1].points()[i]).transpose();
        qd.block(i, 3, 1, 3) = 0.5 * (c[0].points()[i] - c[1].points()[i]).transpose();
    }
    if (!(qd.rightCols(3).cwiseAbs().maxCoeff() > 0.0))
        throw GeometryError("curves: the two outlines coincide; there is no width to rotate");

    const Curve3d dCurve = Curve3d::fromHomogeneous(p, knots, qd.rightCols(3), false);
    ControlMatrix eRows;
    double deviation = 0.0;
    for (;;) {
        const std::vector<double> g = grevilleAbscissae(p, knots);
        ControlMatrix target(static_cast<Eigen::Index>(g.size()), 3);
        for (size_t k = 0; k < g.size(); ++k) target.row(k) = quarterTurn(dCurve.evaluate(g[k]), n).transpose();
        eRows = CurveInterpolator(g, p, knots).solve(target);
        const Curve3d e = Curve3d::fromHomogeneous(p, knots, eRows, false);
        std::vector<double> br{0.0};
        for (double k : interiorBreakpoints(p, knots)) br.push_back(k);
        br.push_back(1.0);
        // The deviation per knot span (samples inside it and at its end).
        std::vector<double> spanDeviation(br.size() - 1, 0.0);
        size_t span = 0;
        for (double u : samples(knots, p)) {
            while (span + 2 < br.size() && u > br[span + 1]) ++span;
            spanDeviation[span] = std::max(spanDeviation[span], (e.evaluate(u) - quarterTurn(dCurve.evaluate(u), n)).norm());
        }
        deviation = *std::max_element(spanDeviation.begin(), spanDeviation.end());
        if (deviation <= tolerance) break;
        // Split the spans over tolerance only, each into as many pieces as the h^(p+1) error of
        // the interpolant asks for (A5.4 keeps Q and D exact).
        std::vector<double> mids;
        for (size_t s = 0; s + 1 < br.size(); ++s) {
            if (!(spanDeviation[s] > tolerance)) continue;
            const double pieces = std::ceil(std::pow(kGrowthMargin * spanDeviation[s] / tolerance, 1.0 / (p + 1)));
            const int m = std::clamp(static_cast<int>(pieces), 2, kMaxPiecesPerPass);
            for (int k = 1; k < m; ++k) mids.push_back(br[s] + (br[s + 1] - br[s]) * k / m);
        }
        if (static_cast<int>(qd.rows() + mids.size()) > options.maxPoints) break;
        KnotsAndPoints r = refineKnots(p, knots, qd, mids);
        knots = std::move(r.knots);
        qd = std::move(r.points);
    }

    // The exact rational full circle: 9 control points of the unit square's corners and edge
    // midpoints, weights 1 and sqrt(2)/2, double knots at the quarters (The NURBS Book Ex. 7.2).
    const double w = std::sqrt(0.5);
    const double cs[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    const KnotVector knotsV{0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    const int nu = static_cast<int>(qd.rows());
    std::vector<Vec3> pts;
    std::vector<double> weights;
    for (int i = 0; i < nu; ++i) {
        const Vec3 q = qd.block(i, 0, 1, 3).transpose();
        const Vec3 d = qd.block(i, 3, 1, 3).transpose();
        const Vec3 e = eRows.row(i).transpose();
        for (int j = 0; j < 9; ++j) {
            pts.push_back(q + cs[j][0] * d + cs[j][1] * e);
            weights.push_back(j % 2 == 1 ? w : 1.0);
        }
    }
    return ApproximatedSurface{Surface3d(p, 2, knots, knotsV, nu, 9, std::move(pts), std::move(weights)), deviation,
                               tolerance};
}

}  // namespace sculptline::solvers::surfaces
