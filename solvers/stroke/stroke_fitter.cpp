#include "solvers/stroke/stroke_fitter.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/periodic.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::stroke {
namespace {

using Vec3 = Eigen::Vector3d;

// A chain of points (the conditioned stroke, rotated to start at a corner when closed) with its
// global chord parameter in [0, 1] and the pieces between consecutive break indices. An open stroke
// is its own chain: `points` and `source` then refer to the conditioned stroke's, not to a copy.
struct Chain {
    Chain() = default;
    Chain(const Chain&) = delete;  // `points` may point into this chain
    Chain& operator=(const Chain&) = delete;
    std::vector<Vec3> rotatedPoints;  // a loop's points from its start corner (empty when open)
    std::vector<int> rotatedSource;
    const std::vector<Vec3>* points = nullptr;
    const std::vector<int>* source = nullptr;  // raw index of each point
    std::vector<double> param;  // global chord parameter, param[0] = 0, param.back() = 1
    std::vector<int> samples;   // indices into points, increasing
    std::vector<int> breaks;    // piece ends: 0, corners.., last
};

struct Assembled {
    KnotVector knots;
    std::vector<Vec3> points;
    std::vector<int> samples;  // indices into the chain
    double maxError = 0.0;
    bool converged = true;
};

// Fits each piece between two breaks as a clamped cubic interpolating its ends, and joins the pieces
// with triple knots (C0, the corner point shared).
Assembled fitPieces(const Chain& c, const SplineFitOptions& opt)
{
    Assembled out;
    const size_t pieces = c.breaks.size() - 1;
    for (size_t p = 0; p < pieces; ++p) {
        const int a = c.breaks[p], b = c.breaks[p + 1];
        // A piece that is the whole chain (no corner) is fitted in place, without a copy.
        const bool whole = a == 0 && b + 1 == static_cast<int>(c.points->size());
        std::vector<Vec3> pts;
        if (!whole) pts.assign(c.points->begin() + a, c.points->begin() + b + 1);
        SplineFitInput in;
        in.points = whole ? c.points : &pts;
        in.chord.reserve(static_cast<size_t>(b - a + 1));
        in.samples.reserve(c.samples.size() + 2);
        const double g0 = c.param[a], g1 = c.param[b], len = g1 - g0;
        for (int i = a; i <= b; ++i) in.chord.push_back(len > 0.0 ? (c.param[i] - g0) / len : double(i - a) / (b - a));
        for (int s : c.samples)
            if (s >= a && s <= b) in.samples.push_back(s - a);
        if (in.samples.empty() || in.samples.front() != 0) in.samples.insert(in.samples.begin(), 0);
        if (in.samples.back() != b - a) in.samples.push_back(b - a);
        const SplineFitResult r = fitCubicSpline(in, opt);
        out.maxError = std::max(out.maxError, r.maxError);
        out.converged = out.converged && r.converged;
        for (int s : r.samples)
            if (out.samples.empty() || s + a > out.samples.back()) out.samples.push_back(s + a);
        // Knots: the first piece keeps its 4 leading knots, every piece drops its final copy except
        // the last (so a joint gets multiplicity 3); points: each later piece drops its first point.
        const size_t k0 = p == 0 ? 0 : 4;
        const size_t k1 = p + 1 == pieces ? r.knots.size() : r.knots.size() - 1;
        for (size_t k = k0; k < k1; ++k) out.knots.push_back(g0 + r.knots[k] * len);
        out.points.insert(out.points.end(), r.points.begin() + (p == 0 ? 0 : 1), r.points.end());
    }
    // Joints are exact: both pieces interpolate the same corner sample.
    out.knots.front() = 0.0;
    return out;
}

// A clamped loop (first point == last point) as a periodic curve in the unwrapped convention of
// BSplineCurve: per period the knots are 0,0,0,s_1..s_k (N = M values for M + 1 clamped points),
// U_i = L[(i-1) mod N] + floor((i-1)/N) so that U_1 = U_2 = U_3 = 0 and P_0 = Q_0 is the seam. The
// chain's parameter, hence the period, is normalized to [0, 1].
Curve3d closeClampedLoop(const KnotVector& clamped, const std::vector<Vec3>& q)
{
    const int nPts = static_cast<int>(q.size()) - 1;  // distinct points Q_0..Q_{M-1}
    const std::vector<double> per(clamped.begin() + 1, clamped.begin() + 1 + nPts);  // 0,0,0,s_1..s_k
    const KnotVector u = periodicKnots(3, per, 1.0);
    std::vector<Vec3> pts(q.begin(), q.end() - 1);
    for (int i = 0; i < 3; ++i) pts.push_back(q[i % nPts]);
    return Curve3d(3, u, pts, {}, true);
}

}  // namespace

FitResult fitStroke(const Stroke& stroke, const FitOptions& options)
{
    FitResult res;
    const ConditioningOptions& copt = options.conditioning;
    // An absolute tolerance caps the merge distance at 0.4 * tolerance (minSpacing relative to the
    // stroke's extent, which conditioning computes anyway).
    ConditionedStroke cs = detail::conditionStrokeWithTolerance(stroke, copt, options.tolerance > 0.0 ? options.tolerance : 0.0);
    res.tolerance = options.tolerance > 0.0 ? options.tolerance : options.relativeTolerance * cs.extent;
    if (!(res.tolerance > 0.0) || !std::isfinite(res.tolerance)) throw GeometryError("tolerance: must be positive and finite");

    std::vector<int> corners, samples;
    {
        // The features are freed before the least squares, which can then reuse their memory.
        const StrokeFeatures f = computeFeatures(cs, options.features);
        corners = detectCorners(cs, f, options.corners);
        smoothPreservingCorners(cs, corners, copt.smoothingPasses);
        if (options.dynamicSampling) {
            samples = dynamicThresholdSamples(cs, f, corners, static_cast<int>(stroke.points.size()), options.sampling);
        } else {
            samples.reserve(static_cast<size_t>(cs.size()));
            for (int i = 0; i < cs.size(); ++i) samples.push_back(i);
        }
    }
    SplineFitOptions sopt = options.spline;
    sopt.tolerance = res.tolerance;
    const int n = cs.size();
    const double total = cs.length();

    if (cs.closed && corners.empty()) {  // smooth loop: periodic least squares
        SplineFitInput in;
        in.points = &cs.points;
        in.closed = true;
        in.chord.reserve(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i) in.chord.push_back(cs.arc[i] / total);
        in.samples = samples;
        if (in.samples.back() == n - 1 && n > 4) in.samples.pop_back();  // keep it: it is inside [0, 1)
        in.samples.push_back(n - 1);
        in.samples.erase(std::unique(in.samples.begin(), in.samples.end()), in.samples.end());
        const SplineFitResult r = fitCubicSpline(in, sopt);
        res.curve = Curve3d(3, r.knots, r.points, {}, true);
        res.maxError = r.maxError;
        res.converged = r.converged;
        res.samples.reserve(r.samples.size());
        for (int s : r.samples) res.samples.push_back(cs.source[s]);
    } else {
        Chain c;
        const int start = cs.closed ? corners.front() : 0;
        const int count = cs.closed ? n + 1 : n;  // a loop repeats its start corner at the end
        std::vector<int> position(n);
        // Sized up front: grown sample by sample, each doubling leaves a hole the rest of the fit
        // cannot reuse, and the first fit of a process pays a page fault for every new heap page.
        c.param.reserve(static_cast<size_t>(count));
        c.samples.reserve(samples.size() + 1);
        if (cs.closed) {
            c.rotatedPoints.reserve(static_cast<size_t>(count));
            c.rotatedSource.reserve(static_cast<size_t>(count));
            for (int k = 0; k < count; ++k) {
                const int i = (start + k) % n;
                if (k < n) position[i] = k;
                c.rotatedPoints.push_back(cs.points[i]);
                c.rotatedSource.push_back(cs.source[i]);
            }
            c.points = &c.rotatedPoints;
            c.source = &c.rotatedSource;
        } else {
            for (int k = 0; k < n; ++k) position[k] = k;
            c.points = &cs.points;
            c.source = &cs.source;
        }
        const std::vector<Vec3>& cp = *c.points;
        double acc = 0.0;
        c.param.push_back(0.0);
        for (size_t k = 1; k < cp.size(); ++k) c.param.push_back(acc += (cp[k] - cp[k - 1]).norm());
        for (double& t : c.param) t /= acc;
        for (int s : samples) c.samples.push_back(position[s]);
        std::sort(c.samples.begin(), c.samples.end());
        if (cs.closed) c.samples.push_back(count - 1);
        c.breaks.push_back(0);
        std::vector<int> inner;
        for (int k : corners) inner.push_back(position[k]);
        std::sort(inner.begin(), inner.end());
        for (int k : inner)
            if (k > 0 && k < count - 1) c.breaks.push_back(k);
        c.breaks.push_back(count - 1);
        const Assembled a = fitPieces(c, sopt);
        res.curve = cs.closed ? closeClampedLoop(a.knots, a.points) : Curve3d(3, a.knots, a.points);
        res.maxError = a.maxError;
        res.converged = a.converged;
        res.samples.reserve(a.samples.size());
        for (int s : a.samples) res.samples.push_back((*c.source)[s]);
        std::sort(res.samples.begin(), res.samples.end());
        res.samples.erase(std::unique(res.samples.begin(), res.samples.end()), res.samples.end());
    }
    res.corners.reserve(corners.size());
    for (int k : corners) res.corners.push_back(cs.source[k]);
    std::sort(res.corners.begin(), res.corners.end());
    res.warnings = cs.warnings;
    if (!res.converged) {
        res.warnings.push_back("fit: maximum deviation " + std::to_string(res.maxError) + " exceeds tolerance " +
                               std::to_string(res.tolerance));
    }
    res.conditioned = std::move(cs);
    return res;
}

}  // namespace sculptline::solvers::stroke
