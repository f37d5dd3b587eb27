#include "solvers/surfaces/coons_fill.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/math_constants.h"
#include "solvers/surfaces/interpolation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
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

// The loop's curves in loop order and direction, normalized, with the corners moved to their
// midpoints; nullopt when a corner gap exceeds the tolerance.
std::optional<std::vector<Curve3d>> loopSides(const std::vector<Curve3d>& curves, const FillLoop& loop)
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
    return s;
}

// The four sides in patch order (bottom, right, top, left), each parameterized on [0, 1] in the
// direction of increasing u or v.
std::array<Curve3d, 4> patchSides(const std::vector<Curve3d>& s)
{
    const size_t n = s.size();
    const Curve3d& s0 = s[0];
    if (n == 4) return std::array<Curve3d, 4>{s0, s[1], reversedCurve(s[2]), reversedCurve(s[3])};
    if (n == 3) return std::array<Curve3d, 4>{s0, s[1], reversedCurve(s[2]), constantCurve(startOf(s0))};
    return std::array<Curve3d, 4>{s0, constantCurve(endOf(s0)), reversedCurve(s[1]), constantCurve(startOf(s0))};
}

// Loop side k is patch side k, except that a lens's second curve is the top (side 2).
int patchSideOf(size_t loopSide, size_t loopSize) { return loopSize == 2 && loopSide == 1 ? 2 : static_cast<int>(loopSide); }

// The layout with the midpoint of every non-empty span inserted.
CurveLayout refinedLayout(const CurveLayout& layout)
{
    CurveLayout out = layout;
    for (size_t k = 0; k + 1 < layout.knots.size(); ++k)
        if (layout.knots[k + 1] > layout.knots[k]) out.knots.push_back(0.5 * (layout.knots[k] + layout.knots[k + 1]));
    std::sort(out.knots.begin(), out.knots.end());
    return out;
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
    if (loop_.order.size() == 3 && !options_.tangents.empty()) {
        // A 3-sided patch collapses the corner where loop side 0 starts (sides 0 and 2 meet): its
        // normal there is a limit the G1 rows do not control, so the loop is turned to keep G1
        // sides off that corner where it can be.
        const auto isG1 = [&](int curve) {
            return std::any_of(options_.tangents.begin(), options_.tangents.end(),
                               [&](const FillTangent& t) { return t.curve == curve; });
        };
        int best = 0, fewest = 3;
        for (int r = 0; r < 3; ++r) {
            const int count = (isG1(loop_.order[r]) ? 1 : 0) + (isG1(loop_.order[(r + 2) % 3]) ? 1 : 0);
            if (count < fewest) {
                fewest = count;
                best = r;
            }
        }
        std::rotate(loop_.order.begin(), loop_.order.begin() + best, loop_.order.end());
        std::rotate(loop_.reversed.begin(), loop_.reversed.begin() + best, loop_.reversed.end());
    }
    const std::optional<std::vector<Curve3d>> ls = loopSides(curves, loop_);
    if (!ls) throw GeometryError("curves: the boundary curves do not meet end to end");
    setupTangents(*ls);
    const std::array<Curve3d, 4> s = patchSides(*ls);
    // G1 needs inner rows that are free of the boundaries: at least cubic across every side.
    const int minDegree = g1_.empty() ? 1 : 3;
    layouts_[0] = commonLayout({s[0], s[2]}, minDegree);
    layouts_[1] = commonLayout({s[3], s[1]}, minDegree);
    for (int d = 0; d < 2; ++d) greville_[d] = grevilleAbscissae(layouts_[d].degree, layouts_[d].knots);
    if (!build(curves)) throw GeometryError("curves: internal error, compatible layout rejected a boundary");
    refineUntilTangent(curves);
    return *surface_;
}

const Surface3d& FillBuilder::update(const std::vector<Curve3d>& curves)
{
    if (curves.size() != loop_.order.size() || !build(curves)) return reset(curves);
    refineUntilTangent(curves);
    return *surface_;
}

void FillBuilder::setupTangents(const std::vector<Curve3d>& ls)
{
    g1_.clear();
    maxAngle_ = 0.0;
    const std::vector<FillTangent>& tangents = options_.tangents;
    if (tangents.empty()) return;
    const double tol = options_.angleToleranceDegrees;
    if (!(tol > 0.0 && tol < 90.0))
        throw GeometryError("tangents: the angle tolerance must be in (0, 90) degrees, got " + std::to_string(tol));
    const size_t n = ls.size();
    for (size_t k = 0; k < tangents.size(); ++k) {
        const std::string name = "tangents[" + std::to_string(k) + "]";
        const int c = tangents[k].curve;
        if (c < 0 || c >= static_cast<int>(n))
            throw GeometryError(name + ": curve " + std::to_string(c) + " is not one of the " + std::to_string(n) +
                                " boundary curves");
        for (size_t j = 0; j < k; ++j)
            if (tangents[j].curve == c)
                throw GeometryError(name + ": curves[" + std::to_string(c) + "] already has a tangent condition (tangents[" +
                                    std::to_string(j) + "])");
        const size_t kl = static_cast<size_t>(std::find(loop_.order.begin(), loop_.order.end(), c) - loop_.order.begin());
        G1Side g;
        g.side = patchSideOf(kl, n);
        g.tangentIndex = static_cast<int>(k);
        g.curveIndex = c;
        g.tracker = std::make_shared<ReferenceTracker>(tangents[k].reference);
        // At each end of the G1 boundary the fill's tangent plane is spanned by the two boundaries
        // meeting there, so the neighbour must leave the corner in the reference's tangent plane.
        for (bool atEnd : {false, true}) {
            const Curve3d& side = ls[kl];
            const Curve3d& other = ls[atEnd ? (kl + 1) % n : (kl + n - 1) % n];
            const Vec3 corner = atEnd ? endOf(side) : startOf(side);
            double gap = 0.0;
            const Eigen::Vector2d uv = g.tracker->locate({corner}, &gap).front();
            if (!(gap <= loop_.tolerance))
                throw GeometryError(name + ": curves[" + std::to_string(c) + "] does not lie on its reference surface: its " +
                                    (atEnd ? "end" : "start") + " is " + std::to_string(gap) + " away (tolerance " +
                                    std::to_string(loop_.tolerance) + ")");
            const Vec3 normal = g.tracker->normal(uv);
            const Vec3 d = other.derivatives(atEnd ? other.domainStart() : other.domainEnd(), 1)[1];
            if (normal.squaredNorm() < 0.5 || d.norm() == 0.0) continue;
            const double off = std::asin(std::min(1.0, std::abs(normal.dot(d.normalized())))) * 180.0 / kPi;
            if (off > tol)
                throw GeometryError(name + ": where curves[" + std::to_string(loop_.order[atEnd ? (kl + 1) % n : (kl + n - 1) % n]) +
                                    "] meets curves[" + std::to_string(c) + "] it leaves the reference surface's tangent plane by " +
                                    std::to_string(off) + " degrees (angle tolerance " + std::to_string(tol) +
                                    "), so no fill can be G1 to the reference along curves[" + std::to_string(c) + "]");
        }
        g1_.push_back(std::move(g));
    }
}

void FillBuilder::refineUntilTangent(const std::vector<Curve3d>& curves)
{
    while (!g1_.empty() && maxAngle_ > options_.angleToleranceDegrees) {
        // Refine along the G1 boundaries: their cross derivative gains freedom span by span.
        std::array<bool, 2> along{false, false};
        for (const G1Side& g : g1_) along[g.side % 2 == 0 ? 0 : 1] = true;
        std::array<CurveLayout, 2> next = layouts_;
        bool grew = false;
        for (int d = 0; d < 2; ++d) {
            if (!along[d]) continue;
            const CurveLayout r = refinedLayout(layouts_[d]);
            if (r.pointCount() <= options_.maxPoints) {
                next[d] = r;
                grew = grew || r.pointCount() > layouts_[d].pointCount();
            }
        }
        if (!grew) return;  // the bound is reached; maxTangentAngleDegrees() reports what was achieved
        layouts_ = next;
        for (int d = 0; d < 2; ++d) greville_[d] = grevilleAbscissae(layouts_[d].degree, layouts_[d].knots);
        if (!build(curves)) throw GeometryError("curves: internal error, refined layout rejected a boundary");
    }
}

bool FillBuilder::build(const std::vector<Curve3d>& curves)
{
    requireFillable(curves);
    const std::optional<std::vector<Curve3d>> ls = loopSides(curves, loop_);
    if (!ls) return false;
    const std::array<Curve3d, 4> sides = patchSides(*ls);
    std::array<std::optional<Curve3d>, 4> c;
    for (int k = 0; k < 4; ++k) {
        c[k] = conformToLayout(sides[k], layouts_[k % 2 == 0 ? 0 : 1]);
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
    if (!g1_.empty()) {
        for (G1Side& g : g1_) locateSamples(g, *c[g.side], layouts_[g.side % 2 == 0 ? 0 : 1], loop_.tolerance);
        applyG1(pts, nu, nv, layouts_, g1_);
    }
    surface_ = std::make_unique<Surface3d>(layouts_[0].degree, layouts_[1].degree, layouts_[0].knots,
                                           layouts_[1].knots, nu, nv, std::move(pts));
    if (!g1_.empty()) maxAngle_ = maxG1AngleDegrees(*surface_, g1_);
    return true;
}

}  // namespace sculptline::solvers::surfaces
