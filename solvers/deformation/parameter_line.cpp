#include "solvers/deformation/parameter_line.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/curve_jet.h"
#include "solvers/bspline/projection.h"
#include "solvers/editing/constrained_fit.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace sculptline::solvers::deformation {
namespace {

Direction other(Direction d) { return d == Direction::U ? Direction::V : Direction::U; }

/// (u, v) of the point at parameter t along a line (the line's own parameter runs in the other
/// direction).
Eigen::Vector2d linePoint(const ParameterLine& line, double t)
{
    return line.fixed == Direction::U ? Eigen::Vector2d(line.value, t) : Eigen::Vector2d(t, line.value);
}

std::vector<double> grevilleAbscissae(const Curve3d& c)
{
    const int p = c.degree();
    std::vector<double> g(static_cast<size_t>(c.pointCount()), 0.0);
    for (int j = 0; j < c.pointCount(); ++j) {
        double sum = 0.0;
        for (int k = 1; k <= p; ++k) sum += c.knots()[static_cast<size_t>(j + k)];
        g[static_cast<size_t>(j)] = sum / p;
    }
    return g;
}

/// A parameter a marking or a line may carry: inside the domain up to round-off of its width.
double checkedParameter(const Surface3d& s, Direction d, double t, const std::string& field)
{
    const double a = s.domainStart(d), b = s.domainEnd(d), slack = 1e-9 * (b - a);
    if (!std::isfinite(t)) throw GeometryError(field + ": not a finite number");
    if (t < a - slack || t > b + slack) {
        throw GeometryError(field + ": " + std::to_string(t) + " is outside the domain [" + std::to_string(a) + ", " +
                            std::to_string(b) + "]");
    }
    return std::clamp(t, a, b);
}

/// Sample parameters of a knot vector's domain: `perSpan` per non-empty span, ends included.
std::vector<double> sampleDomain(int degree, const KnotVector& knots, int count, int perSpan)
{
    std::vector<double> t;
    for (int i = degree; i < count; ++i) {
        const double a = knots[static_cast<size_t>(i)], b = knots[static_cast<size_t>(i + 1)];
        if (b <= a) continue;
        for (int k = 0; k < perSpan; ++k) t.push_back(a + (b - a) * k / perSpan);
    }
    t.push_back(knots[static_cast<size_t>(count)]);
    return t;
}

}  // namespace

ParameterLine pickParameterLine(const Surface3d& surface, const std::vector<Eigen::Vector2d>& uv, const PickOptions& options)
{
    if (uv.size() < 2) throw GeometryError("marking: need at least two points on the surface");
    if (!(options.snapToBoundary >= 0.0 && options.snapToBoundary < 0.5)) throw GeometryError("snapToBoundary: must be in [0, 0.5)");
    std::vector<Eigen::Vector2d> pts;
    for (size_t k = 0; k < uv.size(); ++k) {
        const std::string field = "marking[" + std::to_string(k) + "]";
        pts.emplace_back(checkedParameter(surface, Direction::U, uv[k].x(), field + ".u"),
                         checkedParameter(surface, Direction::V, uv[k].y(), field + ".v"));
    }
    // The dominant direction as seen on the surface: domain steps weighted by the surface's speed.
    double alongU = 0.0, alongV = 0.0;
    for (size_t k = 1; k < pts.size(); ++k) {
        const Eigen::Vector2d mid = 0.5 * (pts[k - 1] + pts[k]);
        const auto d = surface.derivatives(mid.x(), mid.y(), 1);
        alongU += std::abs(pts[k].x() - pts[k - 1].x()) * d[1][0].norm();
        alongV += std::abs(pts[k].y() - pts[k - 1].y()) * d[0][1].norm();
    }
    if (!(alongU + alongV > 0.0)) throw GeometryError("marking: its points coincide on the surface (no direction)");
    ParameterLine line;
    // A marking running along u traces a u-curve: v fixed, and the least-squares v is the mean.
    line.fixed = alongU >= alongV ? Direction::V : Direction::U;
    const int c = line.fixed == Direction::U ? 0 : 1;
    double sum = 0.0;
    for (const auto& p : pts) sum += p[c];
    line.value = sum / static_cast<double>(pts.size());
    const double a = surface.domainStart(line.fixed), b = surface.domainEnd(line.fixed);
    if (line.value - a <= options.snapToBoundary * (b - a)) line.value = a;
    if (b - line.value <= options.snapToBoundary * (b - a)) line.value = b;
    return line;
}

std::vector<Eigen::Vector2d> markingOnSurface(const Surface3d& surface, const std::vector<Eigen::Vector3d>& origins,
                                              const std::vector<Eigen::Vector3d>& directions, double maxDistance)
{
    if (origins.size() != directions.size()) throw GeometryError("marking: one direction per ray origin");
    if (!(maxDistance >= 0.0)) throw GeometryError("maxDistance: must be a non-negative number");
    constexpr int kPerSpan = 8;
    const std::vector<double> us = sampleDomain(surface.degreeU(), surface.knotsU(), surface.countU(), kPerSpan);
    const std::vector<double> vs = sampleDomain(surface.degreeV(), surface.knotsV(), surface.countV(), kPerSpan);
    std::vector<Eigen::Vector3d> grid;
    for (double u : us)
        for (double v : vs) grid.push_back(surface.evaluate(u, v));
    const double a[2] = {surface.domainStart(Direction::U), surface.domainStart(Direction::V)};
    const double b[2] = {surface.domainEnd(Direction::U), surface.domainEnd(Direction::V)};

    // The grid's largest step: how far a seed may be from the ray and still be its nearest sample.
    double cell = 0.0;
    for (size_t i = 0; i < us.size(); ++i) {
        for (size_t j = 0; j < vs.size(); ++j) {
            const size_t g = i * vs.size() + j;
            if (i + 1 < us.size()) cell = std::max(cell, (grid[g + vs.size()] - grid[g]).norm());
            if (j + 1 < vs.size()) cell = std::max(cell, (grid[g + 1] - grid[g]).norm());
        }
    }
    std::vector<Eigen::Vector2d> out;
    for (size_t k = 0; k < origins.size(); ++k) {
        if (!origins[k].allFinite() || !directions[k].allFinite() || directions[k].norm() == 0.0)
            throw GeometryError("marking.rays[" + std::to_string(k) + "]: not a finite ray");
        const Eigen::Vector3d o = origins[k], r = directions[k].normalized();
        const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - r * r.transpose();  // off the ray
        auto offRay = [&](const Eigen::Vector3d& x) { return (P * (x - o)).norm(); };
        // Gauss-Newton on |P (S(u, v) - o)|² from a grid point, clamped to the domain, with step
        // halving; returns the point and its distance from the ray.
        auto refine = [&](size_t g) {
            Eigen::Vector2d x(us[g / vs.size()], vs[g % vs.size()]);
            double dist = offRay(grid[g]);
            for (int it = 0; it < 30; ++it) {
                const auto d = surface.derivatives(x.x(), x.y(), 1);
                const Eigen::Vector3d e = P * (d[0][0] - o);
                Eigen::Matrix<double, 3, 2> J;
                J << P * d[1][0], P * d[0][1];
                const Eigen::Matrix2d JtJ = J.transpose() * J;
                if (std::abs(JtJ.determinant()) <= 1e-300) break;
                Eigen::Vector2d step = -JtJ.inverse() * (J.transpose() * e);
                const double before = dist;
                for (int h = 0; h < 20; ++h, step *= 0.5) {
                    Eigen::Vector2d y = x + step;
                    for (int c = 0; c < 2; ++c) y[c] = std::clamp(y[c], a[c], b[c]);
                    const double dy = offRay(surface.evaluate(y.x(), y.y()));
                    if (dy < dist) {
                        x = y;
                        dist = dy;
                        break;
                    }
                }
                if (!(before - dist > 1e-14 * (1.0 + before))) break;
            }
            return std::make_pair(x, dist);
        };
        // A ray may pass the surface more than once (a jug's front wall, then its back): the
        // person sees the hit nearest the eye. Seeds are the grid points within a cell of the
        // nearest, in depth order; the first that converges onto the ray wins, else the nearest.
        double bestD = std::numeric_limits<double>::infinity();
        for (size_t g = 0; g < grid.size(); ++g) {
            if ((grid[g] - o).dot(r) > 0.0) bestD = std::min(bestD, offRay(grid[g]));
        }
        if (!std::isfinite(bestD)) continue;  // the surface is behind the eye
        std::vector<std::pair<double, size_t>> seeds;
        for (size_t g = 0; g < grid.size(); ++g) {
            const double depth = (grid[g] - o).dot(r);
            if (depth > 0.0 && offRay(grid[g]) <= bestD + cell) seeds.emplace_back(depth, g);
        }
        std::sort(seeds.begin(), seeds.end());
        constexpr size_t kMaxSeeds = 16;
        std::optional<std::pair<Eigen::Vector2d, double>> found;
        for (size_t k2 = 0; k2 < std::min(seeds.size(), kMaxSeeds) && !(found && found->second <= maxDistance); ++k2) {
            const auto hit = refine(seeds[k2].second);
            if (!found || hit.second < found->second) found = hit;
        }
        const Eigen::Vector2d x = found->first;
        const double dist = found->second;
        if (dist <= maxDistance) out.push_back(x);
    }
    if (out.size() < 2) throw GeometryError("marking: fewer than two of its points lie on the surface (draw over it)");
    return out;
}

std::vector<Eigen::Vector2d> markingOnSurface(const Surface3d& surface, const std::vector<Eigen::Vector3d>& points, double maxDistance)
{
    if (!(maxDistance >= 0.0)) throw GeometryError("maxDistance: must be a non-negative number");
    const SurfaceProjector projector(surface);
    std::vector<Eigen::Vector2d> out;
    for (size_t k = 0; k < points.size(); ++k) {
        const std::string field = "marking[" + std::to_string(k) + "]";
        if (!points[k].allFinite()) throw GeometryError(field + ": not a finite number");
        const SurfaceProjection at = projector.project(points[k]);
        if (at.distance > maxDistance) {
            throw GeometryError(field + ": " + std::to_string(at.distance) + " off the surface (more than " +
                                std::to_string(maxDistance) + ")");
        }
        out.emplace_back(at.u, at.v);
    }
    return out;
}

Curve3d parameterLineCurve(const Surface3d& surface, const ParameterLine& line)
{
    const double t = checkedParameter(surface, line.fixed, line.value, "line.value");
    return surface.isoCurve(line.fixed, t);
}

Eigen::Vector3d RuledStrip::ruling(double t) const
{
    const int p = base.degree();
    const int span = findSpan(p, base.knots(), t);
    double N[kMaxDegree + 1];
    basisFunctions(span, t, p, base.knots(), N);
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for (int k = 0; k <= p; ++k) d += N[k] * directors[static_cast<size_t>(span - p + k)];
    return d;
}

Eigen::Vector3d RuledStrip::at(double t, double s) const { return base.evaluate(t) + s * ruling(t); }

RuledStrip makeRuledStrip(const Surface3d& surface, const ParameterLine& line, RulingKind kind, const Eigen::Vector3d& direction)
{
    RuledStrip strip{parameterLineCurve(surface, line), {}};
    const double t0 = checkedParameter(surface, line.fixed, line.value, "line.value");
    const std::vector<double> g = grevilleAbscissae(strip.base);
    if (kind == RulingKind::Constant) {
        if (!direction.allFinite() || direction.norm() == 0.0) throw GeometryError("direction: must be a finite non-zero vector");
        const Eigen::Vector3d d = direction.normalized();
        // Seed 001 §5.2's strip must be a surface: a direction along the line everywhere gives none.
        double worst = 0.0;
        for (double t : sampleDomain(strip.base.degree(), strip.base.knots(), strip.base.pointCount(), 8)) {
            const Eigen::Vector3d tangent = strip.base.derivatives(t, 1)[1];
            if (tangent.norm() > 0.0) worst = std::max(worst, tangent.normalized().cross(d).norm());
        }
        constexpr double kParallelSine = 1e-6;
        if (worst < kParallelSine) throw GeometryError("direction: parallel to the parameter line (the auxiliary surface would be a line)");
        strip.directors.assign(g.size(), d);
        return strip;
    }
    for (double t : g) {
        const Eigen::Vector2d uv = linePoint(line, t);
        Eigen::Vector3d d;
        if (kind == RulingKind::Normal) {
            d = surface.normal(uv.x(), uv.y());
        } else {
            const auto der = surface.derivatives(uv.x(), uv.y(), 1);
            d = line.fixed == Direction::U ? der[1][0] : der[0][1];
            if (t0 == surface.domainStart(line.fixed)) d = -d;  // out of the domain at the start edge
        }
        if (!d.allFinite() || d.norm() == 0.0) {
            throw GeometryError("surface: no " + std::string(kind == RulingKind::Normal ? "normal" : "cross tangent") + " at (u, v) = (" +
                                std::to_string(uv.x()) + ", " + std::to_string(uv.y()) + ")");
        }
        strip.directors.push_back(d.normalized());
    }
    return strip;
}

std::vector<Eigen::Vector3d> projectRaysOntoStrip(const RuledStrip& strip, const std::vector<Eigen::Vector3d>& origins,
                                                  const std::vector<Eigen::Vector3d>& directions, double halfWidth)
{
    if (origins.size() != directions.size()) throw GeometryError("stroke: one direction per ray origin");
    if (!(halfWidth > 0.0) || !std::isfinite(halfWidth)) throw GeometryError("halfWidth: must be a positive number");
    const Curve3d& c = strip.base;
    const std::vector<double> ts = sampleDomain(c.degree(), c.knots(), c.pointCount(), 24);
    std::vector<Eigen::Vector3d> C, D;
    for (double t : ts) {
        C.push_back(c.evaluate(t));
        D.push_back(strip.ruling(t));
    }
    std::vector<Eigen::Vector3d> out;
    for (size_t k = 0; k < origins.size(); ++k) {
        if (!origins[k].allFinite() || !directions[k].allFinite() || directions[k].norm() == 0.0)
            throw GeometryError("stroke.rays[" + std::to_string(k) + "]: not a finite ray");
        const Eigen::Vector3d o = origins[k], r = directions[k].normalized();
        auto f = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& d) { return (x - o).dot(d.cross(r)); };
        std::optional<Eigen::Vector3d> best;
        double bestLambda = std::numeric_limits<double>::infinity();
        auto tryRoot = [&](double t) {
            const Eigen::Vector3d x = c.evaluate(t), d = strip.ruling(t);
            Eigen::Matrix<double, 3, 2> A;
            A << r, -d;
            const Eigen::Matrix2d AtA = A.transpose() * A;
            // A ray along the ruling meets it nowhere or everywhere: no point.
            if (std::abs(AtA.determinant()) <= 1e-12 * AtA.norm() * AtA.norm()) return;
            const Eigen::Vector2d ls = AtA.inverse() * (A.transpose() * (x - o));
            if (ls[0] <= 0.0 || std::abs(ls[1]) > halfWidth || ls[0] >= bestLambda) return;
            bestLambda = ls[0];
            best = x + ls[1] * d;
        };
        double f0 = f(C[0], D[0]);
        if (f0 == 0.0) tryRoot(ts[0]);
        for (size_t i = 1; i < ts.size(); ++i) {
            const double f1 = f(C[i], D[i]);
            if (f1 == 0.0) tryRoot(ts[i]);
            else if ((f0 < 0.0) != (f1 < 0.0) && f0 != 0.0) {
                double lo = ts[i - 1], hi = ts[i], flo = f0;
                for (int it = 0; it < 60; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    const double fm = f(c.evaluate(mid), strip.ruling(mid));
                    if ((fm < 0.0) == (flo < 0.0)) lo = mid, flo = fm;
                    else hi = mid;
                }
                tryRoot(0.5 * (lo + hi));
            }
            f0 = f1;
        }
        if (best) out.push_back(*best);
    }
    return out;
}

ResketchResult resketchLine(const Curve3d& line, const std::vector<Eigen::Vector3d>& stroke, const editing::OversketchOptions& options)
{
    if (line.isRational()) throw GeometryError("line: a rational parameter line cannot be re-sketched (the surface is rational)");
    if (line.isClosed()) throw GeometryError("line: a closed parameter line cannot be re-sketched");
    for (size_t k = 0; k < stroke.size(); ++k) {
        if (!stroke[k].allFinite()) throw GeometryError("stroke.points[" + std::to_string(k) + "]: not a finite number");
    }
    const double a = line.domainStart(), b = line.domainEnd();
    // The surface's domain does not grow: the stroke's points past the line's ends (their foot
    // points on an end) are cut, so that the over-sketch replaces and never extends.
    std::vector<Eigen::Vector3d> inside;
    {
        const CurveProjector<3> projector(line);
        const double slack = 1e-9 * (b - a);
        size_t first = stroke.size(), last = 0;
        std::vector<double> u(stroke.size());
        for (size_t k = 0; k < stroke.size(); ++k) {
            u[k] = projector.project(stroke[k]).u;
            if (u[k] > a + slack && u[k] < b - slack) first = std::min(first, k), last = k;
        }
        if (first <= last && first < stroke.size()) inside.assign(stroke.begin() + static_cast<long>(first), stroke.begin() + static_cast<long>(last) + 1);
    }
    ResketchResult result{line, 0.0, 0.0, 0.0, 0.0, 0};
    std::pair<double, double> span{a, b};
    const Curve3d over = editing::oversketch(line, inside.size() >= 2 ? inside : stroke, options, &span, &result.oversketchError);
    if (std::abs(over.domainStart() - a) > 1e-9 * (b - a) || std::abs(over.domainEnd() - b) > 1e-9 * (b - a))
        throw GeometryError("stroke: runs past the parameter line's end (the surface's domain cannot grow)");
    result.us = span.first;
    result.ue = span.second;

    // Least squares in the line's knot vector; control points whose support misses the replaced
    // span keep their place exactly (the over-sketch left the curve there as it was).
    const int p = line.degree(), n = line.pointCount();
    const KnotVector& K = line.knots();
    editing::FixedKnotFit<3> fit;
    fit.degree = p;
    fit.knots = K;
    fit.fixed.resize(static_cast<size_t>(n));
    for (int j = 0; j < n; ++j) {
        if (K[static_cast<size_t>(j + p + 1)] <= span.first || K[static_cast<size_t>(j)] >= span.second)
            fit.fixed[static_cast<size_t>(j)] = line.points()[static_cast<size_t>(j)];
    }
    // An end the over-sketch left where it was stays exactly (a clamped end is its control point;
    // the over-sketch's transitions may still reach it and report it inside the span).
    const double sameEnd = 1e-12 * std::max(1.0, line.controlSize());
    const bool clampedStart = K[0] == K[static_cast<size_t>(p)], clampedEnd = K[static_cast<size_t>(n)] == K.back();
    if (clampedStart && (over.evaluate(a) - line.evaluate(a)).norm() <= sameEnd) fit.fixed.front() = line.points().front();
    if (clampedEnd && (over.evaluate(b) - line.evaluate(b)).norm() <= sameEnd) fit.fixed.back() = line.points().back();
    // Dense samples: many per span of the over-sketched curve (it has the finer knots).
    constexpr int kSamplesPerSpan = 16;
    for (double t : sampleDomain(over.degree(), over.knots(), over.pointCount(), kSamplesPerSpan)) {
        fit.params.push_back(t);
        fit.samples.push_back(over.evaluate(t));
    }
    std::vector<Eigen::Vector3d> q = editing::fitFixedKnots<3>(fit);
    // Parameter correction (Hoschek's intrinsic parameterization, The NURBS Book §9.4.1's remark):
    // the over-sketch re-parameterizes the replaced span, and fitting its points at its own
    // parameters would also pull the line along itself. Samples move to their foot points on the
    // current fit (a few Newton steps, eq. 6.3), inside the replaced span only, then it is re-fitted.
    constexpr int kCorrections = 4;
    for (int pass = 0; pass < kCorrections; ++pass) {
        const Curve3d current(p, K, q);
        const CurveJet<3> jet(current);
        for (size_t k = 0; k < fit.params.size(); ++k) {
            double& t = fit.params[k];
            if (t <= span.first || t >= span.second) continue;
            for (int step = 0; step < 3; ++step) {
                Eigen::Vector3d x, d1, d2;
                jet.evaluate(t, x, d1, d2);
                if (!footPointNewtonStep(x, d1, d2, fit.samples[k], span.first, span.second, t)) break;
            }
        }
        q = editing::fitFixedKnots<3>(fit);
    }
    result.curve = Curve3d(p, K, q);
    // Geometric: the over-sketched curve's points against their foot points on the new line.
    const CurveProjector<3> onNew(result.curve);
    for (double t : sampleDomain(over.degree(), over.knots(), over.pointCount(), 2 * kSamplesPerSpan))
        result.knotFitError = std::max(result.knotFitError, onNew.project(over.evaluate(t)).distance);
    for (int j = 0; j < n; ++j) result.movedPoints += q[static_cast<size_t>(j)] != line.points()[static_cast<size_t>(j)] ? 1 : 0;
    return result;
}

Surface3d followParameterLine(const Surface3d& surface, const ParameterLine& line, const Curve3d& target)
{
    if (surface.isRational()) throw GeometryError("surface: rational surfaces cannot follow a re-sketched line");
    const double t = checkedParameter(surface, line.fixed, line.value, "line.value");
    const Direction along = other(line.fixed);
    if (target.isRational() || target.degree() != surface.degree(along) || target.knots() != surface.knots(along) ||
        target.pointCount() != surface.count(along)) {
        throw GeometryError("target: must have the surface's degree and knot vector along the line");
    }
    for (const auto& q : target.points()) {
        if (!q.allFinite()) throw GeometryError("target.points: not a finite number");
    }
    const Curve3d current = surface.isoCurve(line.fixed, t);
    const int p = surface.degree(line.fixed);
    const int span = findSpan(p, surface.knots(line.fixed), t);
    double N[kMaxDegree + 1];
    basisFunctions(span, t, p, surface.knots(line.fixed), N);
    double norm2 = 0.0;
    for (int k = 0; k <= p; ++k) norm2 += N[k] * N[k];  // >= 1/(p+1): Σ N = 1

    std::vector<Eigen::Vector3d> pts = surface.points();
    const int nv = surface.countV();
    for (int j = 0; j < target.pointCount(); ++j) {
        const Eigen::Vector3d dq = target.points()[static_cast<size_t>(j)] - current.points()[static_cast<size_t>(j)];
        if (dq.isZero(0.0)) continue;
        for (int k = 0; k <= p; ++k) {
            if (N[k] == 0.0) continue;
            const int i = span - p + k;  // the row index in the fixed direction
            const size_t index = line.fixed == Direction::U ? static_cast<size_t>(i) * nv + j : static_cast<size_t>(j) * nv + i;
            pts[index] += (N[k] / norm2) * dq;
        }
    }
    return Surface3d(surface.degreeU(), surface.degreeV(), surface.knotsU(), surface.knotsV(), surface.countU(), surface.countV(),
                     std::move(pts));
}

}  // namespace sculptline::solvers::deformation
