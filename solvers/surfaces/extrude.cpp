#include "solvers/surfaces/extrude.h"

#include "solvers/bspline/geometry_error.h"

#include <algorithm>
#include <sstream>
#include <string>

namespace sculptline::solvers::surfaces {

namespace {

// A translation shorter than this fraction of the profile's size sweeps out no surface.
constexpr double kMinExtentRelative = 1e-12;

std::string shortNumber(double x)
{
    std::ostringstream s;
    s << x;
    return s.str();
}

void requireExtent(const Curve3d& profile, double scale)
{
    if (!(profile.controlSize() > kMinExtentRelative * scale))
        throw GeometryError("curves: the profile is a single point, extruding it gives no surface");
}

}  // namespace

Surface3d extrude(const Curve3d& input, const Eigen::Vector3d& direction)
{
    const Curve3d profile = input.clamped();
    const double size = std::max(1.0, profile.controlSize());
    if (!direction.allFinite()) throw GeometryError("direction: not a finite number");
    // stableNorm: the plain norm of a 1e300 vector overflows to infinity.
    const double length = direction.stableNorm();
    if (!(length > kMinExtentRelative * size)) {
        throw GeometryError(length == 0.0 ? std::string("direction: zero length, nothing to extrude")
                                          : "direction: length " + shortNumber(length) +
                                                " is below round-off against the profile's size " + shortNumber(size));
    }
    // The profile must stay resolvable against the translation too: beyond 1e12 times its size its
    // points would differ only in the last digits of the surface's coordinates.
    if (profile.controlSize() > 0.0 && !(profile.controlSize() > kMinExtentRelative * length)) {
        throw GeometryError("direction: length " + shortNumber(length) + " dwarfs the profile (size " +
                            shortNumber(profile.controlSize()) + "), which would vanish in round-off");
    }
    requireExtent(profile, std::max(1.0, length));
    const int n = profile.pointCount();
    std::vector<Eigen::Vector3d> pts;
    std::vector<double> w;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2; ++j) {
            pts.push_back(profile.points()[i] + (j == 0 ? Eigen::Vector3d::Zero() : direction));
            if (profile.isRational()) w.push_back(profile.weight(i));
        }
    return Surface3d(profile.degree(), 1, profile.knots(), {0.0, 0.0, 1.0, 1.0}, n, 2, std::move(pts), std::move(w));
}

Surface3d extrude(const Curve3d& input, const Curve3d& inputPath)
{
    const Curve3d profile = input.clamped();
    const Curve3d path = inputPath.clamped();
    const double size = std::max(1.0, profile.controlSize());
    double extent = 0.0;
    const Eigen::Vector3d start = path.evaluate(path.domainStart());
    for (const Eigen::Vector3d& q : path.points()) extent = std::max(extent, (q - start).norm());
    if (!(extent > kMinExtentRelative * size)) throw GeometryError("path: zero length, nothing to extrude");
    requireExtent(profile, std::max(1.0, extent));
    const bool rational = profile.isRational() || path.isRational();
    std::vector<Eigen::Vector3d> pts;
    std::vector<double> w;
    // With weights w_i·w_j the rational sums factor: sum N_i N_j w_i w_j (P_i + Q_j - Q0) /
    // (sum N_i w_i)(sum N_j w_j) = C(u) + D(v) - Q0.
    for (int i = 0; i < profile.pointCount(); ++i)
        for (int j = 0; j < path.pointCount(); ++j) {
            pts.push_back(profile.points()[i] + path.points()[j] - start);
            if (rational) w.push_back(profile.weight(i) * path.weight(j));
        }
    return Surface3d(profile.degree(), path.degree(), profile.knots(), path.knots(), profile.pointCount(),
                     path.pointCount(), std::move(pts), std::move(w));
}

}  // namespace sculptline::solvers::surfaces
