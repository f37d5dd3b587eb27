#include "solvers/bspline/projection.h"

#include "solvers/bspline/geometry_error.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::solvers {
namespace {

// Newton iterations per candidate: quadratic convergence needs < 10 from a bracketed start; the
// rest is for the bisection fallback (each halves the bracket: 2^-60 is below double resolution).
constexpr int kMaxIterations = 80;

// A grid cell's patch lies within the box of its nine sample points (corners, edge midpoints,
// middle) padded by this multiple of their bulge: the largest distance of an edge midpoint from its
// corners' mean, or of the middle from the four corners' mean. That is the second-order term of the
// patch over the cell (an eighth of a knot span on a side by default); the cubic terms beyond the
// samples are smaller still, so twice the bulge holds the patch, at the price of a few extra
// Newton runs where it is generous.
constexpr double kCellBulge = 2.0;

// Cells per block side in the search's first level (a block of 8 x 8 cells is a knot-span pair at
// the default 8 samples per span): on the 18 x 135 sculpt sheet's 120 x 264 cells (kMaxGridSamples),
// a point tests ~500 block boxes and the cells of the few near blocks instead of every cell box.
constexpr size_t kBlockCells = 8;

// The cell search's budget per point: the nearest-bound cells searched at most. A fitted or
// sculpted surface leaves a handful of cells whose box is nearer than the grid's best (the boat's
// folded last section: a few); a net with a wild control point (a fuzzer's 6.7e32 among unit
// spacings) makes every cell's box huge and every cell a candidate, 576 cells x 5 Newton runs per
// point, 6 s for one incidence input under ASan. Beyond the budget the best point found is kept.
constexpr size_t kMaxCellSearches = 64;
// And at most this many surface evaluations (derivatives or points) in those cells' Newton runs.
// The projection unit tests pass with it (the fold needs 2,640 for its worst point; the dense-grid
// test spends up to 5,488 but has its minimum before 3,000). The fuzzer's net spent about 16,000
// per point (32 points, 10,240 Newton runs): 6 s an execution under ASan, 1.4 s with this budget.
constexpr long kCellSearchEvaluations = 3000;

// Surface Newton stops once a step moves (u, v) by less than this share of the domain's width in
// each direction: converged to round-off (the point moves by |S_u| times that), where the line
// search would otherwise keep halving steps of 1e-13 for up to 40 evaluations each.
constexpr double kStepResolution = 1e-12;

// The coarse grid's samples per direction at most: a direction with more knot spans than this
// allows at samplesPerSpan gets fewer samples per span (never fewer than 2). The grid is the
// search's start, not its accuracy: the padded cell boxes keep every patch inside them at any
// density, and Newton finishes the foot. Without a cap the 18 x 135 sculpt sheet's grid held
// 121 x 1,057 samples and its refinement 509,000 surface evaluations, 46 % of the fuzz target's
// profile under ASan for a projector that then places 34 key points. 256 keeps the default density
// on every surface up to 32 spans per direction.
constexpr int kMaxGridSamples = 256;

// Samples per span in a direction of `spans` non-empty knot spans: `wanted`, or fewer to stay
// within kMaxGridSamples, and at least 2.
int samplesPerSpanWithin(int wanted, int spans)
{
    return std::clamp(kMaxGridSamples / std::max(1, spans), 2, std::max(2, wanted));
}

int nonEmptySpans(int degree, const KnotVector& knots, int count)
{
    int spans = 0;
    for (int i = degree; i < count; ++i) spans += knots[i] != knots[i + 1] ? 1 : 0;
    return spans;
}

std::vector<double> sampleParameters(int degree, const KnotVector& knots, int count, int perSpan)
{
    std::vector<double> out;
    for (int i = degree; i < count; ++i) {
        if (knots[i] == knots[i + 1]) continue;
        for (int k = 0; k < perSpan; ++k) out.push_back(knots[i] + (knots[i + 1] - knots[i]) * k / perSpan);
    }
    out.push_back(knots[count]);
    return out;
}

}  // namespace

template <int Dim>
CurveProjector<Dim>::CurveProjector(BSplineCurve<Dim> curve, int samplesPerSpan)
    : curve_(std::move(curve)), jet_(curve_)
{
    params_ = sampleParameters(curve_.degree(), curve_.knots(), curve_.pointCount(), std::max(2, samplesPerSpan));
    samples_.reserve(params_.size());
    for (double u : params_) samples_.push_back(curve_.evaluate(u));
}

template <int Dim>
double CurveProjector<Dim>::refine(const Point& x, double lo, double hi, double u) const
{
    // Safeguarded Newton (Numerical Recipes' rtsafe idea) on f(u) = C'(u)·(C(u) - x), which is
    // negative left of a local minimum of the distance and positive right of it.
    auto f = [&](double t, double* df) {
        // The parameter wrapped as BSplineCurve::derivatives does (brackets cross a closed curve's seam).
        Point c, d1, d2;
        jet_.evaluate(curve_.normalizeParameter(t), c, d1, d2);
        const Point r = c - x;
        if (df) *df = d2.dot(r) + d1.squaredNorm();
        return d1.dot(r);
    };
    const double resolution = 4 * std::numeric_limits<double>::epsilon() * std::max({1.0, std::abs(lo), std::abs(hi)});
    // At a knot the kernel evaluates the span to its right; the upper end needs the left limit
    // (they differ at a C0 corner), hence the step one ulp inside.
    double flo = f(lo, nullptr), fhi = f(std::nextafter(hi, lo), nullptr);
    if (!(flo < 0 && fhi > 0)) {
        // No sign change: the minimum is at a bracket end (or the bracket holds an inflexion).
        const double dl = (curve_.evaluate(lo) - x).squaredNorm(), dh = (curve_.evaluate(hi) - x).squaredNorm();
        const double du = (curve_.evaluate(u) - x).squaredNorm();
        return du <= std::min(dl, dh) ? u : (dl <= dh ? lo : hi);
    }
    for (int iter = 0; iter < kMaxIterations && hi - lo > resolution; ++iter) {
        double df = 0.0;
        const double fu = f(u, &df);
        if (fu == 0.0) break;
        if (fu < 0) lo = u;
        else hi = u;
        double next = df > 0 ? u - fu / df : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
        if (std::abs(next - u) <= resolution) {
            u = next;
            break;
        }
        u = next;
    }
    return u;
}

template <int Dim>
CurveProjection<Dim> CurveProjector<Dim>::project(const Point& x) const
{
    if (!x.allFinite()) throw GeometryError("points: not a finite number");
    const size_t n = samples_.size();
    std::vector<double> d2(n);
    for (size_t i = 0; i < n; ++i) d2[i] = (samples_[i] - x).squaredNorm();
    const bool closed = curve_.isClosed();
    const double T = curve_.domainEnd() - curve_.domainStart();
    // For a closed curve the last sample repeats the first; neighbours wrap around.
    const size_t m = closed ? n - 1 : n;
    CurveProjection<Dim> best;
    best.distance = std::numeric_limits<double>::infinity();
    auto consider = [&](double u) {
        const Point c = curve_.evaluate(u);
        const double dist = (c - x).norm();
        if (dist < best.distance) {
            best.u = curve_.normalizeParameter(u);
            best.point = c;
            best.distance = dist;
        }
    };
    for (size_t i = 0; i < m; ++i) {
        double lo, hi;
        double dl, dh;
        if (i == 0) {
            if (closed) {
                lo = params_[m - 1] - T;
                dl = d2[m - 1];
            } else {
                lo = params_[0];
                dl = std::numeric_limits<double>::infinity();
            }
        } else {
            lo = params_[i - 1];
            dl = d2[i - 1];
        }
        if (i + 1 == m && closed) {
            hi = params_[0] + T;
            dh = d2[0];
        } else if (i + 1 >= n) {
            hi = params_[i];
            dh = std::numeric_limits<double>::infinity();
        } else {
            hi = params_[i + 1];
            dh = d2[i + 1];
        }
        if (d2[i] <= dl && d2[i] <= dh) {
            // A sampled local minimum: each side of the sample may hold a minimum of its own (at a
            // C0 knot the distance has one on each side of the corner), so refine both halves.
            const double u = params_[i];
            consider(u);
            if (lo < u) consider(refine(x, lo, u, 0.5 * (lo + u)));
            if (u < hi) consider(refine(x, u, hi, 0.5 * (u + hi)));
        }
    }
    if (!closed) {
        consider(curve_.domainStart());
        consider(curve_.domainEnd());
    }
    return best;
}

template <int Dim>
CurveProjection<Dim> projectToCurve(const BSplineCurve<Dim>& curve, const Eigen::Matrix<double, Dim, 1>& x)
{
    return CurveProjector<Dim>(curve).project(x);
}

SurfaceProjector::SurfaceProjector(BSplineSurface<3> surface, int samplesPerSpan)
    : surface_(std::move(surface)), jet_(surface_)
{
    const int perU = samplesPerSpanWithin(samplesPerSpan, nonEmptySpans(surface_.degreeU(), surface_.knotsU(), surface_.countU()));
    const int perV = samplesPerSpanWithin(samplesPerSpan, nonEmptySpans(surface_.degreeV(), surface_.knotsV(), surface_.countV()));
    us_ = sampleParameters(surface_.degreeU(), surface_.knotsU(), surface_.countU(), perU);
    vs_ = sampleParameters(surface_.degreeV(), surface_.knotsV(), surface_.countV(), perV);
    // The grid and, per cell, its edge midpoints and middle: one evaluation of the surface on the
    // grid refined by the midpoints (each point shared by the cells around it).
    const size_t nu = us_.size(), nv = vs_.size();
    auto refined = [](const std::vector<double>& t) {
        std::vector<double> out;
        out.reserve(2 * t.size());
        for (size_t k = 0; k < t.size(); ++k) {
            if (k > 0) out.push_back(0.5 * (t[k - 1] + t[k]));
            out.push_back(t[k]);
        }
        return out;
    };
    const std::vector<double> uf = refined(us_), vf = refined(vs_);
    const std::vector<Eigen::Vector3d> fine = surface_.evaluateGrid(uf, vf);
    const size_t nvf = vf.size();
    auto at = [&](size_t a, size_t b) -> const Eigen::Vector3d& { return fine[a * nvf + b]; };
    grid_.reserve(nu * nv);
    for (size_t i = 0; i < nu; ++i)
        for (size_t j = 0; j < nv; ++j) grid_.push_back(at(2 * i, 2 * j));
    if (nu > 1 && nv > 1) {
        cellLow_.reserve((nu - 1) * (nv - 1));
        cellHigh_.reserve((nu - 1) * (nv - 1));
    }
    for (size_t i = 0; i + 1 < nu; ++i) {
        for (size_t j = 0; j + 1 < nv; ++j) {
            const Eigen::Vector3d& a = at(2 * i, 2 * j);
            const Eigen::Vector3d& b = at(2 * i, 2 * j + 2);
            const Eigen::Vector3d& c = at(2 * i + 2, 2 * j);
            const Eigen::Vector3d& d = at(2 * i + 2, 2 * j + 2);
            const Eigen::Vector3d& mid = at(2 * i + 1, 2 * j + 1);
            const Eigen::Vector3d edge[4] = {at(2 * i, 2 * j + 1), at(2 * i + 2, 2 * j + 1), at(2 * i + 1, 2 * j),
                                             at(2 * i + 1, 2 * j + 2)};
            const Eigen::Vector3d ends[4][2] = {{a, b}, {c, d}, {a, c}, {b, d}};
            double bulge = (mid - 0.25 * (a + b + c + d)).norm();
            Eigen::Vector3d lo = mid.cwiseMin(a).cwiseMin(b).cwiseMin(c).cwiseMin(d);
            Eigen::Vector3d hi = mid.cwiseMax(a).cwiseMax(b).cwiseMax(c).cwiseMax(d);
            for (int k = 0; k < 4; ++k) {
                bulge = std::max(bulge, (edge[k] - 0.5 * (ends[k][0] + ends[k][1])).norm());
                lo = lo.cwiseMin(edge[k]);
                hi = hi.cwiseMax(edge[k]);
            }
            const Eigen::Vector3d pad = Eigen::Vector3d::Constant(kCellBulge * bulge);
            cellLow_.push_back(lo - pad);
            cellHigh_.push_back(hi + pad);
        }
    }
    if (nu > 1 && nv > 1) {
        const size_t cu = nu - 1, cv = nv - 1;
        const size_t bu = (cu + kBlockCells - 1) / kBlockCells, bv = (cv + kBlockCells - 1) / kBlockCells;
        blockCountV_ = static_cast<int>(bv);
        blockLow_.assign(bu * bv, Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()));
        blockHigh_.assign(bu * bv, Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity()));
        for (size_t i = 0; i < cu; ++i) {
            for (size_t j = 0; j < cv; ++j) {
                const size_t b = (i / kBlockCells) * bv + j / kBlockCells;
                blockLow_[b] = blockLow_[b].cwiseMin(cellLow_[i * cv + j]);
                blockHigh_[b] = blockHigh_[b].cwiseMax(cellHigh_[i * cv + j]);
            }
        }
    }
    const double u0 = surface_.domainStart(Direction::U), u1 = surface_.domainEnd(Direction::U);
    const double v0 = surface_.domainStart(Direction::V), v1 = surface_.domainEnd(Direction::V);
    for (double u : {u0, u1}) {
        boundaries_.emplace_back(surface_.isoCurve(Direction::U, u));
        boundaryParams_.emplace_back(0, u);
    }
    for (double v : {v0, v1}) {
        boundaries_.emplace_back(surface_.isoCurve(Direction::V, v));
        boundaryParams_.emplace_back(1, v);
    }
}

SurfaceProjection SurfaceProjector::newton(const Eigen::Vector3d& x, double u, double v, double u0, double u1, double v0,
                                           double v1, long* budget) const
{
    double dist2 = (surface_.evaluate(u, v) - x).squaredNorm();
    const double uWidth = us_.back() - us_.front(), vWidth = vs_.back() - vs_.front();
    for (int iter = 0; iter < kMaxIterations && !(budget && *budget <= 0); ++iter) {
        if (budget) --*budget;
        const SurfaceJet::Values d = jet_.evaluate(u, v);
        const Eigen::Vector3d r = d.s - x;
        // Gradient and Hessian of |S - x|^2 / 2 (The NURBS Book eqs. 6.6-6.7).
        const Eigen::Vector2d g(r.dot(d.su), r.dot(d.sv));
        Eigen::Matrix2d H;
        H(0, 0) = d.su.squaredNorm() + r.dot(d.suu);
        H(0, 1) = H(1, 0) = d.su.dot(d.sv) + r.dot(d.suv);
        H(1, 1) = d.sv.squaredNorm() + r.dot(d.svv);
        Eigen::Vector2d step;
        const Eigen::LDLT<Eigen::Matrix2d> ldlt(H);
        if (ldlt.info() == Eigen::Success && ldlt.isPositive() && H.determinant() > 0) {
            step = -ldlt.solve(g);
        } else {
            // Not locally convex: a gradient step scaled by the first-order metric.
            const double a = std::max(H(0, 0), d.su.squaredNorm()), b = std::max(H(1, 1), d.sv.squaredNorm());
            step = Eigen::Vector2d(-g[0] / std::max(a, 1e-300), -g[1] / std::max(b, 1e-300));
        }
        // Backtracking line search on the clamped step: the distance never increases.
        double t = 1.0;
        bool moved = false;
        for (int k = 0; k < 40; ++k, t *= 0.5) {
            if (budget) --*budget;
            const double nu = std::clamp(u + t * step[0], u0, u1), nv = std::clamp(v + t * step[1], v0, v1);
            const double nd = (surface_.evaluate(nu, nv) - x).squaredNorm();
            if (nd < dist2) {
                moved = std::abs(nu - u) > kStepResolution * uWidth || std::abs(nv - v) > kStepResolution * vWidth;
                u = nu;
                v = nv;
                dist2 = nd;
                break;
            }
        }
        if (!moved) break;
    }
    SurfaceProjection out;
    out.u = u;
    out.v = v;
    out.point = surface_.evaluate(u, v);
    out.distance = (out.point - x).norm();
    return out;
}

SurfaceProjection SurfaceProjector::project(const Eigen::Vector3d& x) const
{
    if (!x.allFinite()) throw GeometryError("points: not a finite number");
    const int nu = static_cast<int>(us_.size()), nv = static_cast<int>(vs_.size());
    std::vector<double> d2(grid_.size());
    for (size_t i = 0; i < grid_.size(); ++i) d2[i] = (grid_[i] - x).squaredNorm();
    SurfaceProjection best;
    best.distance = std::numeric_limits<double>::infinity();
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            const double here = d2[static_cast<size_t>(i) * nv + j];
            bool isMin = true;
            for (int di = -1; di <= 1 && isMin; ++di)
                for (int dj = -1; dj <= 1; ++dj) {
                    const int a = i + di, b = j + dj;
                    if ((di || dj) && a >= 0 && a < nu && b >= 0 && b < nv && d2[static_cast<size_t>(a) * nv + b] < here) {
                        isMin = false;
                        break;
                    }
                }
            if (!isMin) continue;
            const SurfaceProjection c = newton(x, us_[i], vs_[j], us_.front(), us_.back(), vs_.front(), vs_.back());
            if (c.distance < best.distance) best = c;
        }
    }
    for (size_t k = 0; k < boundaries_.size(); ++k) {
        const CurveProjection<3> c = boundaries_[k].project(x);
        if (c.distance < best.distance) {
            best.u = boundaryParams_[k].first == 0 ? boundaryParams_[k].second : c.u;
            best.v = boundaryParams_[k].first == 0 ? c.u : boundaryParams_[k].second;
            best.point = surface_.evaluate(best.u, best.v);
            best.distance = (best.point - x).norm();
        }
    }
    // Cells that may still hold a closer point, nearest bound first: each is searched by Newton
    // kept inside it (a minimum on its edge is also its neighbour's), until no bound is below the
    // best distance found. Newton starts from the cell's centre and from its four corners: a cell
    // can hold two sheets of a folded surface (the boat's jittered last section passes 0.012 mm
    // from the foot point of an exported vertex within the same cell), and from the centre alone
    // Newton went to the far sheet (vertices projected 1.3-2.1 um off instead of 6e-7; starting
    // only where the centre's Newton ended on the cell's edge missed more: the far sheet's own
    // minimum can lie inside the cell).
    std::vector<std::pair<double, int>> cells;
    const size_t cv = vs_.empty() ? 0 : vs_.size() - 1;
    for (size_t b = 0; b < blockLow_.size(); ++b) {
        if (!((x - x.cwiseMax(blockLow_[b]).cwiseMin(blockHigh_[b])).norm() < best.distance)) continue;
        const size_t bi = b / static_cast<size_t>(blockCountV_), bj = b % static_cast<size_t>(blockCountV_);
        const size_t iEnd = std::min((bi + 1) * kBlockCells, us_.size() - 1), jEnd = std::min((bj + 1) * kBlockCells, cv);
        for (size_t i = bi * kBlockCells; i < iEnd; ++i) {
            for (size_t j = bj * kBlockCells; j < jEnd; ++j) {
                const size_t k = i * cv + j;
                const double lower = (x - x.cwiseMax(cellLow_[k]).cwiseMin(cellHigh_[k])).norm();
                if (lower < best.distance) cells.emplace_back(lower, static_cast<int>(k));
            }
        }
    }
    std::sort(cells.begin(), cells.end());
    // At most kMaxCellSearches cells and kCellSearchEvaluations evaluations, nearest bound first.
    if (cells.size() > kMaxCellSearches) cells.resize(kMaxCellSearches);
    long budget = kCellSearchEvaluations;
    for (const auto& [lower, k] : cells) {
        if (!(lower < best.distance) || budget <= 0) break;
        const int i = k / (nv - 1), j = k % (nv - 1);
        const double starts[5][2] = {{0.5 * (us_[i] + us_[i + 1]), 0.5 * (vs_[j] + vs_[j + 1])},
                                     {us_[i], vs_[j]}, {us_[i + 1], vs_[j]}, {us_[i], vs_[j + 1]}, {us_[i + 1], vs_[j + 1]}};
        for (const auto& st : starts) {
            const SurfaceProjection c = newton(x, st[0], st[1], us_[i], us_[i + 1], vs_[j], vs_[j + 1], &budget);
            if (c.distance < best.distance) best = c;
        }
    }
    return best;
}

SurfaceProjection projectToSurface(const BSplineSurface<3>& surface, const Eigen::Vector3d& x)
{
    return SurfaceProjector(surface).project(x);
}

template class CurveProjector<2>;
template class CurveProjector<3>;
template CurveProjection<2> projectToCurve<2>(const BSplineCurve<2>&, const Eigen::Vector2d&);
template CurveProjection<3> projectToCurve<3>(const BSplineCurve<3>&, const Eigen::Vector3d&);

}  // namespace sculptline::solvers
