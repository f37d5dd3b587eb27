#include "solvers/surfaces/revolve.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/math_constants.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

namespace sculptline::solvers::surfaces {

namespace {

// An axis direction shorter than this, relative to the magnitude of the axis point's coordinates
// (at least 1), is the round-off of two coincident points (an axis drawn from a closed curve): it
// has no direction. Not relative to the profile: a profile of size 1e300 about a unit direction is
// a valid revolve.
constexpr double kMinAxisLength = 1e-12;
// Control points closer to the axis than this fraction of the profile's size count as on it.
constexpr double kOnAxisRelative = 1e-12;
// Profile samples per knot span for the axis-crossing test.
constexpr int kCrossingSamplesPerSpan = 32;

// Throws when the profile passes from one side of the axis to the other: its radial direction
// turns by more than 90 degrees between neighbouring dense samples (planar profiles: the signed
// distance changes sign). The revolved surface would then pass through itself. Touching the axis
// and turning back, or ending on it (a pole), is fine.
void requireNoAxisCrossing(const Curve3d& profile, const Eigen::Vector3d& point, const Eigen::Vector3d& T, double size)
{
    std::vector<double> breaks{profile.domainStart()};
    for (double k : interiorBreakpoints(profile.degree(), profile.knots())) breaks.push_back(k);
    breaks.push_back(profile.domainEnd());
    Eigen::Vector3d last = Eigen::Vector3d::Zero();
    for (size_t s = 0; s + 1 < breaks.size(); ++s)
        for (int k = 0; k <= kCrossingSamplesPerSpan; ++k) {
            const double u = breaks[s] + (breaks[s + 1] - breaks[s]) * k / kCrossingSamplesPerSpan;
            const Eigen::Vector3d d = profile.evaluate(u) - point;
            const Eigen::Vector3d radial = d - d.dot(T) * T;
            if (radial.norm() <= kOnAxisRelative * size) continue;
            if (last.squaredNorm() > 0.0 && radial.dot(last) < 0.0)
                throw GeometryError("curves: the profile crosses the axis near u = " + std::to_string(u) +
                                    "; the revolved surface would pass through itself (end the profile on the axis)");
            last = radial;
        }
}

}  // namespace

double distanceFromAxis(const Axis& axis, const Eigen::Vector3d& x)
{
    const Eigen::Vector3d t = axis.direction.stableNormalized();
    const Eigen::Vector3d d = x - axis.point;
    return (d - d.dot(t) * t).norm();
}

Surface3d revolve(const Curve3d& input, const Axis& axis, double angleDegrees)
{
    const Curve3d profile = input.clamped();
    const double size = std::max(1.0, profile.controlSize());
    // stableNorm: a direction of length 1e300 is a direction too, but its squared norm overflows
    // and normalized() would divide by infinity (a zero axis, every point collapsed onto it).
    if (!axis.direction.allFinite() || !axis.point.allFinite()) throw GeometryError("axis: not a finite number");
    const double axisScale = std::max(1.0, axis.point.cwiseAbs().maxCoeff());
    if (!(axis.direction.stableNorm() > kMinAxisLength * axisScale)) throw GeometryError("axis: zero-length direction");
    if (!(angleDegrees > 0.0 && angleDegrees <= 360.0))
        throw GeometryError("angle: must be in (0, 360] degrees, got " + std::to_string(angleDegrees));

    // A8.1: number of arcs, their knots and the middle weight cos(dtheta / 2).
    const double theta = angleDegrees * kPi / 180.0;
    const int narcs = angleDegrees <= 90.0 ? 1 : angleDegrees <= 180.0 ? 2 : angleDegrees <= 270.0 ? 3 : 4;
    const double dtheta = theta / narcs;
    const double wm = std::cos(dtheta / 2.0);
    KnotVector knotsV{0.0, 0.0, 0.0};
    for (int k = 1; k < narcs; ++k) knotsV.insert(knotsV.end(), 2, static_cast<double>(k) / narcs);
    knotsV.insert(knotsV.end(), 3, 1.0);
    const int countV = 2 * narcs + 1;

    const Eigen::Vector3d T = axis.direction.stableNormalized();
    const int countU = profile.pointCount();
    std::vector<Eigen::Vector3d> pts(static_cast<size_t>(countU) * countV);
    std::vector<double> w(pts.size());
    double maxRadius = 0.0;
    for (int i = 0; i < countU; ++i) {
        const Eigen::Vector3d& P = profile.points()[i];
        const Eigen::Vector3d O = axis.point + (P - axis.point).dot(T) * T;
        Eigen::Vector3d X = P - O;
        const double r = X.norm();
        maxRadius = std::max(maxRadius, r);
        // A point on the axis revolves into itself (a pole); any X serves.
        X = r > kOnAxisRelative * size ? Eigen::Vector3d(X / r) : T.unitOrthogonal();
        const Eigen::Vector3d Y = T.cross(X);
        const double wi = profile.weight(i);
        for (int j = 0; j < countV; ++j) {
            // Even j: on the circle at angle (j/2)·dtheta; odd j: the tangent lines' intersection
            // at the arc's middle angle, radius r / cos(dtheta/2), weight wm (The NURBS Book §7.5).
            const double angle = 0.5 * j * dtheta;
            const bool middle = j % 2 == 1;
            const double radius = middle ? r / wm : r;
            const size_t idx = static_cast<size_t>(i) * countV + j;
            pts[idx] = j == 0 ? P : Eigen::Vector3d(O + radius * (std::cos(angle) * X + std::sin(angle) * Y));
            w[idx] = wi * (middle ? wm : 1.0);
        }
    }
    if (!(maxRadius > kOnAxisRelative * size))
        throw GeometryError("curves: the profile lies on the axis, revolving it gives no surface");
    if (!(profile.controlSize() > kOnAxisRelative * size))
        throw GeometryError("curves: the profile is a single point, revolving it gives no surface");
    requireNoAxisCrossing(profile, axis.point, T, size);
    return Surface3d(profile.degree(), 2, profile.knots(), knotsV, countU, countV, std::move(pts), std::move(w));
}

}  // namespace sculptline::solvers::surfaces
