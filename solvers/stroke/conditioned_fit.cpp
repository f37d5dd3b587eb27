#include "solvers/stroke/conditioned_fit.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/periodic.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::stroke::detail {
namespace {

struct Assembled {
    KnotVector knots;
    std::vector<Vec3> points;
    std::vector<int> samples;  // indices into the chain
    double maxError = 0.0;
    bool converged = true;
    AveragedCorrectionState correction;  // a single piece's (SplineFitOptions::averagedStopWhenWithin)
};

// Fits each piece between two breaks as a clamped cubic interpolating its ends, and joins the pieces
// with triple knots (C0, the corner point shared).
Assembled fitPieces(const Chain& c, const SplineFitOptions& opt)
{
    Assembled out;
    const size_t pieces = c.breaks.size() - 1;
    // Corrections stopped early are resumed for one piece only (the search fits no more).
    SplineFitOptions single;
    const SplineFitOptions* o = &opt;
    if (pieces > 1 && (opt.averagedStopWhenWithin || opt.averagedResume)) {
        single = opt;
        single.averagedStopWhenWithin = false;
        single.averagedResume = nullptr;
        o = &single;
    }
    // (Sized for the whole chain up front, as fitConditioned's: grown piece by piece they were
    // reallocated several times a fit.)
    out.samples.reserve(c.samples.size() + pieces + 1);
    std::vector<Vec3> pts;  // a piece's points (storage reused from piece to piece)
    for (size_t p = 0; p < pieces; ++p) {
        const int a = c.breaks[p], b = c.breaks[p + 1];
        // A piece that is the whole chain (no corner) is fitted in place, without a copy.
        const bool whole = a == 0 && b + 1 == static_cast<int>(c.points->size());
        if (!whole) pts.assign(c.points->begin() + a, c.points->begin() + b + 1);
        SplineFitInput in;
        in.points = whole ? c.points : &pts;
        in.chord = c.pieceChord[p].empty() ? &c.param : &c.pieceChord[p];
        in.samples.reserve(c.samples.size() + 2);
        const double g0 = c.param[a], g1 = c.param[b], len = g1 - g0;
        for (int s : c.samples)
            if (s >= a && s <= b) in.samples.push_back(s - a);
        if (in.samples.empty() || in.samples.front() != 0) in.samples.insert(in.samples.begin(), 0);
        if (in.samples.back() != b - a) in.samples.push_back(b - a);
        SplineFitResult r = fitCubicSpline(in, *o);
        if (pieces == 1) out.correction = std::move(r.correction);
        out.maxError = std::max(out.maxError, r.maxError);
        out.converged = out.converged && r.converged;
        for (int s : r.samples)
            if (out.samples.empty() || s + a > out.samples.back()) out.samples.push_back(s + a);
        appendClampedPiece(r.knots, r.points, 0.0, 1.0, g0, len, p == 0, p + 1 == pieces, out.knots, out.points);
    }
    // Joints are exact: both pieces interpolate the same corner sample.
    out.knots.front() = 0.0;
    return out;
}

}  // namespace

void appendClampedPiece(const KnotVector& knots, const std::vector<Vec3>& points, double d0, double d1, double g0,
                        double len, bool first, bool last, KnotVector& outKnots, std::vector<Vec3>& outPoints)
{
    // Knots: the first piece keeps its 4 leading knots, every piece drops its final copy except the
    // last (so a joint gets multiplicity 3); points: each later piece drops its first point.
    const size_t k0 = first ? 0 : 4;
    const size_t k1 = last ? knots.size() : knots.size() - 1;
    for (size_t k = k0; k < k1; ++k) outKnots.push_back(g0 + (knots[k] - d0) / (d1 - d0) * len);
    outPoints.insert(outPoints.end(), points.begin() + (first ? 0 : 1), points.end());
}

// A clamped loop (first point == last point) as a periodic curve in the unwrapped convention of
// BSplineCurve: per period the knots are 0,0,0,s_1..s_k (N = M values for M + 1 clamped points),
// U_i = L[(i-1) mod N] + floor((i-1)/N) so that U_1 = U_2 = U_3 = 0 and P_0 = Q_0 is the seam. The
// chain's parameter, hence the period, is normalized to [0, 1].
Curve3d closeClampedLoop(const KnotVector& clamped, const std::vector<Vec3>& q)
{
    const int nPts = static_cast<int>(q.size()) - 1;                                 // distinct points Q_0..Q_{M-1}
    const std::vector<double> per(clamped.begin() + 1, clamped.begin() + 1 + nPts);  // 0,0,0,s_1..s_k
    const KnotVector u = periodicKnots(3, per, 1.0);
    std::vector<Vec3> pts(q.begin(), q.end() - 1);
    for (int i = 0; i < 3; ++i) pts.push_back(q[i % nPts]);
    return Curve3d(3, u, pts, {}, true);
}

FitPass fitConditioned(const ConditionedStroke& cs, const std::vector<Vec3>& fitPoints, const std::vector<int>& corners,
                       const std::vector<int>& samples, const SplineFitOptions& sopt,
                       const std::vector<Vec3>* paramPoints, Chain* chain)
{
    FitPass out;
    const int n = cs.size();
    const double total = cs.length();
    Chain local;
    Chain& c = chain ? *chain : local;

    if (cs.closed && corners.empty()) {  // smooth loop: periodic least squares
        if (!c.built) {
            c.loopChord.reserve(static_cast<size_t>(n));
            for (int i = 0; i < n; ++i) c.loopChord.push_back(cs.arc[i] / total);
            c.built = true;
        }
        SplineFitInput in;
        in.points = &fitPoints;
        in.closed = true;
        in.chord = &c.loopChord;
        in.samples = samples;
        if (in.samples.back() == n - 1 && n > 4) in.samples.pop_back();  // keep it: it is inside [0, 1)
        in.samples.push_back(n - 1);
        in.samples.erase(std::unique(in.samples.begin(), in.samples.end()), in.samples.end());
        SplineFitResult r = fitCubicSpline(in, sopt);
        out.curve = Curve3d(3, r.knots, r.points, {}, true);
        out.correction = std::move(r.correction);
        out.maxError = r.maxError;
        out.converged = r.converged;
        out.samples.reserve(r.samples.size());
        for (int s : r.samples) out.samples.push_back(cs.source[s]);
    } else {
        const int count = cs.closed ? n + 1 : n;  // a loop repeats its start corner at the end
        if (!c.built) {
            const int start = cs.closed ? corners.front() : 0;
            c.position.resize(static_cast<size_t>(n));
            // Sized up front: grown sample by sample, each doubling leaves a hole the rest of the fit
            // cannot reuse, and the first fit of a process pays a page fault for every new heap page.
            c.param.reserve(static_cast<size_t>(count));
            if (cs.closed) {
                c.rotatedPoints.reserve(static_cast<size_t>(count));
                c.rotatedSource.reserve(static_cast<size_t>(count));
                for (int k = 0; k < count; ++k) {
                    const int i = (start + k) % n;
                    if (k < n) c.position[i] = k;
                    c.rotatedPoints.push_back(fitPoints[i]);
                    c.rotatedSource.push_back(cs.source[i]);
                }
                c.points = &c.rotatedPoints;
                c.source = &c.rotatedSource;
            } else {
                for (int k = 0; k < n; ++k) c.position[k] = k;
                c.points = &fitPoints;
                c.source = &cs.source;
            }
            const std::vector<Vec3>& cp = paramPoints ? *paramPoints : cs.points;
            double acc = 0.0;
            c.param.push_back(0.0);
            for (int k = 1; k < count; ++k)
                c.param.push_back(acc += (cp[(start + k) % n] - cp[(start + k - 1) % n]).norm());
            for (double& t : c.param) t /= acc;
            c.breaks.push_back(0);
            std::vector<int> inner;
            for (int k : corners) inner.push_back(c.position[k]);
            std::sort(inner.begin(), inner.end());
            for (int k : inner)
                if (k > 0 && k < count - 1) c.breaks.push_back(k);
            c.breaks.push_back(count - 1);
            c.pieceChord.resize(c.breaks.size() - 1);
            for (size_t p = 0; p + 1 < c.breaks.size(); ++p) {
                const int a = c.breaks[p], b = c.breaks[p + 1];
                const double g0 = c.param[a], len = c.param[b] - g0;
                if (a == 0 && b == count - 1 && len > 0.0) continue;  // the whole chain: `param` itself
                auto& chord = c.pieceChord[p];
                chord.reserve(static_cast<size_t>(b - a + 1));
                for (int i = a; i <= b; ++i)
                    chord.push_back(len > 0.0 ? (c.param[i] - g0) / len : double(i - a) / (b - a));
            }
            c.built = true;
        }
        c.samples.clear();
        c.samples.reserve(samples.size() + 1);
        for (int s : samples) c.samples.push_back(c.position[s]);
        // (An open chain's rows come in order; a loop's are rotated to its start corner.)
        if (!std::is_sorted(c.samples.begin(), c.samples.end())) std::sort(c.samples.begin(), c.samples.end());
        if (cs.closed) c.samples.push_back(count - 1);
        Assembled a = fitPieces(c, sopt);
        out.correction = std::move(a.correction);
        out.curve = cs.closed ? closeClampedLoop(a.knots, a.points) : Curve3d(3, a.knots, a.points);
        out.maxError = a.maxError;
        out.converged = a.converged;
        out.samples.reserve(a.samples.size());
        for (int s : a.samples) out.samples.push_back((*c.source)[s]);
        if (!std::is_sorted(out.samples.begin(), out.samples.end())) std::sort(out.samples.begin(), out.samples.end());
        out.samples.erase(std::unique(out.samples.begin(), out.samples.end()), out.samples.end());
    }
    return out;
}

}  // namespace sculptline::solvers::stroke::detail
