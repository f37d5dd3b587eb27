#pragma once
// Shared checks for the surface-interpreter tests: distances between a surface's iso-curves and
// the curves that define them, and normal consistency over a grid.
#include "solvers/bspline/bspline_surface.h"
#include "solvers/math_constants.h"
#include "solvers/surfaces/surface_modes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

namespace sculptline::surfaces_test {

using solvers::Curve3d;
using solvers::Surface3d;
using Vec3 = Eigen::Vector3d;

/// What "exact" means for the modes that pass through their defining curves (loft, revolve,
/// extrude, Coons fill, Gordon, ...): 1e-9 on models of size ~1-10, a thousand times the round-off
/// the kernel's own invariant tests allow (1e-12) and far below any drawing tolerance.
constexpr double kExact = 1e-9;

/// The modes of the single entry point (surfaces::buildSurface) that tests run one by one.
constexpr solvers::surfaces::SurfaceMode kModes[] = {
    solvers::surfaces::SurfaceMode::Fill,  solvers::surfaces::SurfaceMode::Revolve,
    solvers::surfaces::SurfaceMode::Extrude, solvers::surfaces::SurfaceMode::Sweep,
    solvers::surfaces::SurfaceMode::Loft,  solvers::surfaces::SurfaceMode::BoundaryRotation,
    solvers::surfaces::SurfaceMode::RailRotation};
using solvers::kPi;  // the solvers' one (solvers/math_constants.h)

/// Cubic clamped uniform curve through (not interpolating) the given control points.
inline Curve3d cubic(const std::vector<Vec3>& pts) { return solvers::makeClampedUniform<3>(3, pts); }

/// Largest |S(u(t), v(t)) - C(t)| over `samples` parameters t in [0, 1], where (u, v) runs along the
/// iso-line `fixed` (0: u = value varies v; 1: v = value, varies u) mapped from the domains.
inline double isoDeviation(const Surface3d& s, bool vFixed, double value, const Curve3d& c, bool reversed = false,
                           int samples = 101)
{
    double worst = 0.0;
    for (int k = 0; k < samples; ++k) {
        const double t = static_cast<double>(k) / (samples - 1);
        const double tc = c.domainStart() + (reversed ? 1.0 - t : t) * (c.domainEnd() - c.domainStart());
        const solvers::Direction free = vFixed ? solvers::Direction::U : solvers::Direction::V;
        const double ts = s.domainStart(free) + t * (s.domainEnd(free) - s.domainStart(free));
        const Vec3 p = vFixed ? s.evaluate(ts, value) : s.evaluate(value, ts);
        worst = std::max(worst, (p - c.evaluate(tc)).norm());
    }
    return worst;
}

/// Distance from S(u, v) to a boundary curve: the smallest isoDeviation over the four iso-edges in
/// either direction (each input curve of a fill must be one of them).
inline double boundaryDeviation(const Surface3d& s, const Curve3d& c)
{
    double best = 1e300;
    for (bool vFixed : {true, false})
        for (double value : {0.0, 1.0})
            for (bool rev : {false, true}) best = std::min(best, isoDeviation(s, vFixed, value, c, rev));
    return best;
}

/// Unit normal with the limit at collapsed edges (poles). Surface3d::normal tests degeneracy by
/// |Su x Sv| relative to |Su||Sv|, which does not catch a derivative that is round-off noise
/// (~1e-15) rather than exactly zero at a pole, and its limit Su x Suv has the wrong sign at an
/// edge collapsed at the end of the domain (there Sv ~ (u - u_end)·Suv with u - u_end < 0); both
/// reported to the kernel owner. Here a derivative below kCollapsed times the other counts as
/// vanished and the one-sided limit is used.
inline Vec3 limitNormal(const Surface3d& s, double u, double v)
{
    constexpr double kCollapsed = 1e-10;
    const auto d = s.derivatives(u, v, 2);
    const Vec3 &su = d[1][0], &sv = d[0][1], &suv = d[1][1];
    Vec3 n = su.cross(sv);
    const double uSide = u >= s.domainEnd(solvers::Direction::U) ? -1.0 : 1.0;
    const double vSide = v >= s.domainEnd(solvers::Direction::V) ? -1.0 : 1.0;
    if (sv.norm() <= kCollapsed * su.norm()) n = uSide * su.cross(suv);
    else if (su.norm() <= kCollapsed * sv.norm()) n = vSide * suv.cross(sv);
    return n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
}

/// The smallest dot product between unit normals at neighbouring points of an n x n grid (points
/// where the normal is undefined, such as poles, are skipped). Negative means a flip.
inline double minNeighbourNormalDot(const Surface3d& s, int n = 40)
{
    std::vector<Vec3> normals;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double u = s.domainStart(solvers::Direction::U) +
                             (s.domainEnd(solvers::Direction::U) - s.domainStart(solvers::Direction::U)) * i / (n - 1);
            const double v = s.domainStart(solvers::Direction::V) +
                             (s.domainEnd(solvers::Direction::V) - s.domainStart(solvers::Direction::V)) * j / (n - 1);
            normals.push_back(limitNormal(s, u, v));
        }
    double worst = 1.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3& a = normals[i * n + j];
            if (a.norm() < 0.5) continue;
            if (i + 1 < n && normals[(i + 1) * n + j].norm() > 0.5) worst = std::min(worst, a.dot(normals[(i + 1) * n + j]));
            if (j + 1 < n && normals[i * n + j + 1].norm() > 0.5) worst = std::min(worst, a.dot(normals[i * n + j + 1]));
        }
    return worst;
}

}  // namespace sculptline::surfaces_test

namespace sculptline::surfaces_test {

/// The exact full circle (9-point rational, The NURBS Book Ex. 7.2) of radius r about `centre` in
/// the plane spanned by the unit vectors a (u = 0) and b (u = 1/4).
inline Curve3d fullCircle(const Vec3& centre, double r, const Vec3& a, const Vec3& b)
{
    const double w = std::sqrt(0.5);
    const double cs[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    std::vector<Vec3> pts;
    std::vector<double> ws;
    for (int j = 0; j < 9; ++j) {
        pts.push_back(centre + r * (cs[j][0] * a + cs[j][1] * b));
        ws.push_back(j % 2 == 1 ? w : 1.0);
    }
    return Curve3d(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, pts, ws);
}

}  // namespace sculptline::surfaces_test
