#include "solvers/surfaces/coons_fill.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/interpolation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <optional>
#include <string>

namespace sculptline::solvers::surfaces {

namespace {

using Vec3 = Eigen::Vector3d;

Vec3 startOf(const Curve3d& c) { return c.evaluate(c.domainStart()); }
Vec3 endOf(const Curve3d& c) { return c.evaluate(c.domainEnd()); }

void requireFillable(const std::vector<Curve3d>& curves)
{
    if (curves.size() < 2 || curves.size() > 4)
        throw GeometryError("curves: a fill needs 2, 3 or 4 boundary curves, got " + std::to_string(curves.size()));
    for (size_t k = 0; k < curves.size(); ++k)
        if (curves[k].isRational())
            throw GeometryError("curves[" + std::to_string(k) +
                                "]: rational boundaries are not supported by the Coons fill (the blend of "
                                "rational sides is not a NURBS patch)");
}

double meetTolerance(const std::vector<Curve3d>& curves, const FillOptions& options)
{
    if (options.meetTolerance > 0.0) return options.meetTolerance;
    Eigen::AlignedBox3d box;
    for (const Curve3d& c : curves)
        for (const Vec3& p : c.points()) box.extend(p);
    return kDefaultMeetRelative * std::max(box.diagonal().norm(), std::numeric_limits<double>::min());
}

// A curve with its end control point (the end point of a clamped curve) replaced.
Curve3d withEnd(const Curve3d& c, bool atEnd, const Vec3& p)
{
    std::vector<Vec3> pts = c.points();
    (atEnd ? pts.back() : pts.front()) = p;
    return Curve3d(c.degree(), c.knots(), std::move(pts), c.weights());
}

Curve3d constantCurve(const Vec3& p) { return Curve3d(1, {0.0, 0.0, 1.0, 1.0}, {p, p}); }

// The four sides in patch order (bottom, right, top, left), each parameterized on [0, 1] in the
// direction of increasing u or v, with the loop's corners moved to their midpoints; nullopt when
// a corner gap exceeds the tolerance.
std::optional<std::array<Curve3d, 4>> patchSides(const std::vector<Curve3d>& curves, const FillLoop& loop)
{
    const size_t n = loop.order.size();
    std::vector<Curve3d> s;
    for (size_t k = 0; k < n; ++k) {
        const Curve3d c = normalizedCurve(curves[loop.order[k]]);
        s.push_back(loop.reversed[k] ? reversedCurve(c) : c);
    }
    for (size_t k = 0; k < n; ++k) {
        Curve3d& a = s[k];
        Curve3d& b = s[(k + 1) % n];
        const Vec3 ea = endOf(a);
        const Vec3 sb = startOf(b);
        if ((ea - sb).norm() > loop.tolerance) return std::nullopt;
        const Vec3 mid = 0.5 * (ea + sb);
        a = withEnd(a, true, mid);
        b = withEnd(b, false, mid);
    }
    const Curve3d& s0 = s[0];
    if (n == 4) return std::array<Curve3d, 4>{s0, s[1], reversedCurve(s[2]), reversedCurve(s[3])};
    if (n == 3) return std::array<Curve3d, 4>{s0, s[1], reversedCurve(s[2]), constantCurve(startOf(s0))};
    return std::array<Curve3d, 4>{s0, constantCurve(endOf(s0)), reversedCurve(s[1]), constantCurve(startOf(s0))};
}

}  // namespace

FillLoop chainBoundaries(const std::vector<Curve3d>& curves, const FillOptions& options)
{
    requireFillable(curves);
    FillLoop loop;
    loop.tolerance = meetTolerance(curves, options);
    const size_t n = curves.size();
    std::vector<bool> used(n, false);
    loop.order.push_back(0);
    loop.reversed.push_back(false);
    used[0] = true;
    Vec3 current = endOf(curves[0]);
    for (size_t k = 1; k < n; ++k) {
        int best = -1;
        bool bestReversed = false;
        double bestGap = std::numeric_limits<double>::infinity();
        for (size_t c = 0; c < n; ++c) {
            if (used[c]) continue;
            for (bool rev : {false, true}) {
                const double gap = (current - (rev ? endOf(curves[c]) : startOf(curves[c]))).norm();
                if (gap < bestGap) {
                    bestGap = gap;
                    best = static_cast<int>(c);
                    bestReversed = rev;
                }
            }
        }
        if (!(bestGap <= loop.tolerance))
            throw GeometryError("curves: the boundary curves do not meet end to end: after curves[" +
                                std::to_string(loop.order.back()) + "] the nearest free end is " + std::to_string(bestGap) +
                                " away (tolerance " + std::to_string(loop.tolerance) + ")");
        used[best] = true;
        loop.order.push_back(best);
        loop.reversed.push_back(bestReversed);
        loop.maxGap = std::max(loop.maxGap, bestGap);
        current = bestReversed ? startOf(curves[best]) : endOf(curves[best]);
    }
    const double closing = (current - startOf(curves[0])).norm();
    if (!(closing <= loop.tolerance))
        throw GeometryError("curves: the boundary curves do not close: the loop's last end is " + std::to_string(closing) +
                            " away from its start (tolerance " + std::to_string(loop.tolerance) + ")");
    loop.maxGap = std::max(loop.maxGap, closing);
    return loop;
}

Surface3d fill(const std::vector<Curve3d>& curves, const FillOptions& options)
{
    return FillBuilder(curves, options).surface();
}

FillBuilder::FillBuilder(const std::vector<Curve3d>& curves, const FillOptions& options) : options_(options)
{
    reset(curves);
}

const Surface3d& FillBuilder::reset(const std::vector<Curve3d>& curves)
{
    loop_ = chainBoundaries(curves, options_);
    const std::optional<std::array<Curve3d, 4>> sides = patchSides(curves, loop_);
    if (!sides) throw GeometryError("curves: the boundary curves do not meet end to end");
    const std::array<Curve3d, 4>& s = *sides;
    layouts_[0] = commonLayout({s[0], s[2]});
    layouts_[1] = commonLayout({s[3], s[1]});
    for (int d = 0; d < 2; ++d) greville_[d] = grevilleAbscissae(layouts_[d].degree, layouts_[d].knots);
    if (!build(curves)) throw GeometryError("curves: internal error, compatible layout rejected a boundary");
    return *surface_;
}

const Surface3d& FillBuilder::update(const std::vector<Curve3d>& curves)
{
    if (curves.size() != loop_.order.size() || !build(curves)) return reset(curves);
    return *surface_;
}

bool FillBuilder::build(const std::vector<Curve3d>& curves)
{
    requireFillable(curves);
    const std::optional<std::array<Curve3d, 4>> sides = patchSides(curves, loop_);
    if (!sides) return false;
    std::array<std::optional<Curve3d>, 4> c;
    for (int k = 0; k < 4; ++k) {
        c[k] = conformToLayout((*sides)[k], layouts_[k % 2 == 0 ? 0 : 1]);
        if (!c[k]) return false;
    }
    const std::vector<Vec3>& B = c[0]->points();  // v = 0
    const std::vector<Vec3>& R = c[1]->points();  // u = 1
    const std::vector<Vec3>& T = c[2]->points();  // v = 1
    const std::vector<Vec3>& L = c[3]->points();  // u = 0
    const Vec3 P00 = B.front(), P10 = B.back(), P01 = T.front(), P11 = T.back();
    const std::vector<double>& gu = greville_[0];
    const std::vector<double>& gv = greville_[1];
    const int nu = static_cast<int>(gu.size());
    const int nv = static_cast<int>(gv.size());
    std::vector<Vec3> pts(static_cast<size_t>(nu) * nv);
    // Coons: ruled(B, T) in v + ruled(L, R) in u - bilinear(corners). A polynomial of degree 1 in
    // v has B-spline coefficients equal to its values at the Greville abscissae (linear precision,
    // Farin ch. 8), so each term's control net is its formula evaluated there.
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = gu[i];
            const double v = gv[j];
            pts[static_cast<size_t>(i) * nv + j] = (1 - v) * B[i] + v * T[i] + (1 - u) * L[j] + u * R[j] -
                                                   ((1 - u) * (1 - v) * P00 + u * (1 - v) * P10 +
                                                    (1 - u) * v * P01 + u * v * P11);
        }
    // A degenerate side (3 or 2 curves) is collapsed exactly: the sum above leaves round-off of
    // order 1e-16 there, and a surface whose edge derivative is noise instead of zero has noise for
    // a normal at that edge (the kernel's limit normal needs an exactly vanishing derivative).
    const auto collapse = [&](int i, const std::vector<Vec3>& side) {
        if (std::all_of(side.begin(), side.end(), [&](const Vec3& p) { return p == side.front(); }))
            for (int j = 0; j < nv; ++j) pts[static_cast<size_t>(i) * nv + j] = side.front();
    };
    collapse(0, L);
    collapse(nu - 1, R);
    surface_ = std::make_unique<Surface3d>(layouts_[0].degree, layouts_[1].degree, layouts_[0].knots,
                                           layouts_[1].knots, nu, nv, std::move(pts));
    return true;
}

}  // namespace sculptline::solvers::surfaces
