// local-c2 over-sketching: seed 001 (Kim & Kim), §3 (break points, h̄) and §4 (Alg. 1-1, 1-2).
//
// Reading of the garbled parts, chosen here:
// - u_ps = u_s - d1 mixes a parameter and a length in the PDF; we step back d1 in arc length.
// - The constrained control points and the marks z_k, z_l with eqs. 1-2 (interpolating or
//   extrapolating P_{k-2}, P_{l-2} as knots are inserted near the marks) are the knot-insertion
//   update of the control points that the old curve's end pieces impose on the new knot vector. We
//   compute them in closed form by blossoming (Ramshaw 1989; The NURBS Book §5.2): for a control
//   point j whose support contains the old span r = [t_{k-1}, t_k], P_j = b_r(U'_{j+1}, .., U'_{j+p})
//   with b_r the blossom of the old piece on r and U' the current new knots. Eq. 1 is this formula
//   after one insertion. All p such points on each side are pinned (the paper pins two per side,
//   which leaves the span before t_k free to move); pinning p makes the curve outside [t_k, t_l]
//   identical up to round-off and the joint C^{p-1}, i.e. C2 for cubics.
#include "solvers/editing/oversketch.h"

#include "solvers/bspline/arc_length.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/periodic.h"
#include "solvers/editing/constrained_fit.h"
#include "solvers/editing/oversketch_support.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::editing::detail {
namespace {

// Alg. 1-1 stops adding knots once a span would hold fewer than two samples of h̄ on average.
constexpr int kSamplesPerKnotMin = 2;

template <int Dim>
using Pt = Eigen::Matrix<double, Dim, 1>;

// Blossom of the degree-p polynomial piece on span r at x[0..p-1]: de Boor's evaluation triangle
// with the k-th level taking the k-th argument instead of u (Ramshaw 1989, "Blossoms are polar
// forms"; with all x = u it is The NURBS Book's de Boor recurrence, eq. 5.15 form).
template <typename V>
V blossom(const KnotVector& U, const std::vector<V>& P, int p, int r, const double* x)
{
    V d[kMaxDegree + 1];
    for (int j = 0; j <= p; ++j) d[j] = P[r - p + j];
    for (int k = 1; k <= p; ++k) {
        for (int j = p; j >= k; --j) {
            const int i = r - p + j;
            const double alpha = (x[k - 1] - U[i]) / (U[i + p + 1 - k] - U[i]);
            d[j] = (1.0 - alpha) * d[j - 1] + alpha * d[j];
        }
    }
    return d[p];
}

// Homogeneous control point (w·P, w): rational curves are blossomed (knot-inserted) in this space,
// where they are polynomial (The NURBS Book §5.2); non-rational ones carry w = 1.
template <int Dim>
using Hp = Eigen::Matrix<double, Dim + 1, 1>;

template <int Dim>
Pt<Dim> cartesian(const Hp<Dim>& h)
{
    return h.template head<Dim>() / h[Dim];
}

template <int Dim>
struct Edit {
    KnotVector knots;
    std::vector<Pt<Dim>> points;
    std::vector<double> weights;  // empty for a non-rational curve
    int localFirst = 0, localLast = 0;  // new indices of the points that may differ
    double error = 0.0;
};

// Alg. 1-1 on an open (possibly unclamped) window: knots U, homogeneous points P. [tk, tl] are knot
// values; leftFree/rightFree mark a clamped end where the new curve interpolates h̄'s end instead.
// Rational curves: the pinned points come with their blossomed weights, the free points get weights
// interpolated linearly (by index) between the pinned ones next to them, so the untouched parts keep
// theirs; with the weights fixed the fit stays linear in the Cartesian points.
template <int Dim>
Edit<Dim> localApproximation(int p, const KnotVector& U, const std::vector<Hp<Dim>>& P, bool rational, double tk,
                             double tl, bool leftFree, bool rightFree, const std::vector<double>& params,
                             const std::vector<Pt<Dim>>& target, double tolerance)
{
    const int a = static_cast<int>(std::upper_bound(U.begin(), U.end(), tk) - U.begin());      // knots <= tk
    const int ibOld = static_cast<int>(std::lower_bound(U.begin(), U.end(), tl) - U.begin());  // first == tl
    const int ibLastOld = static_cast<int>(std::upper_bound(U.begin(), U.end(), tl) - U.begin()) - 1;
    const int rLeft = a - 1 - static_cast<int>(std::count(U.begin(), U.begin() + a, tk));  // last span ending at tk

    // Initial interior knots: p + 1 equal spans, the fewest that leave a free point between the
    // p pinned on each side.
    std::vector<double> interior;
    for (int i = 1; i <= p + 1; ++i) interior.push_back(tk + (tl - tk) * i / (p + 2));
    const int maxInterior = std::max(p + 1, static_cast<int>(params.size()) / kSamplesPerKnotMin);

    Edit<Dim> e;
    for (;;) {
        KnotVector Un(U.begin(), U.begin() + a);
        Un.insert(Un.end(), interior.begin(), interior.end());
        Un.insert(Un.end(), U.begin() + ibOld, U.end());
        const int s = static_cast<int>(interior.size());
        const int ibNew = a + s, delta = ibNew - ibOld;
        const int L0 = a - p - 1, L1 = ibNew - 1;

        FixedKnotFit<Dim> fit;
        fit.degree = p;
        fit.knots.assign(Un.begin() + L0, Un.begin() + L1 + p + 2);
        fit.params = params;
        fit.samples = target;
        fit.fixed.assign(L1 - L0 + 1, std::nullopt);
        std::vector<double> w(L1 - L0 + 1, 0.0);  // 0: free weight, set below
        auto pin = [&](int j, const Hp<Dim>& h) {
            fit.fixed[j - L0] = cartesian<Dim>(h);
            w[j - L0] = h[Dim];
        };
        if (leftFree) {
            fit.fixed.front() = target.front();
            w.front() = P[L0][Dim];
        } else {
            for (int j = std::max(rLeft - p, L0); j <= rLeft; ++j) pin(j, blossom(U, P, p, rLeft, &Un[j + 1]));
        }
        if (rightFree) {
            fit.fixed.back() = target.back();
            w.back() = P[ibOld - 1][Dim];  // the clamped end's old point
        } else {
            const int rNew = ibLastOld + delta;
            for (int j = rNew - p; j <= L1; ++j) pin(j, blossom(U, P, p, ibLastOld, &Un[j + 1]));
        }
        if (rational) {  // free weights: linear by index between the known ones, constant beyond them
            int last = -1;
            for (int i = 0; i < static_cast<int>(w.size()); ++i) {
                if (w[i] == 0.0) continue;
                for (int j = last + 1; j < i; ++j) {
                    w[j] = last < 0 ? w[i] : w[last] + (w[i] - w[last]) * (j - last) / (i - last);
                }
                last = i;
            }
            for (int j = last + 1; j < static_cast<int>(w.size()); ++j) w[j] = w[last];
            fit.weights = w;
        }
        const std::vector<Pt<Dim>> local = fitFixedKnots(fit);

        // Alg. 1-1 steps 3-5: the max error over h̄, and the most deviated knot span, read as the
        // largest sum of squared errors of its samples. (Splitting the span that holds the single
        // worst sample, the other reading, was measured to halve the same span again and again when
        // the worst sample sits next to a knot whose other neighbour is the one too long.) Only
        // spans holding at least kSamplesPerKnotMin samples are split: a finer span is undetermined.
        double worst = 0.0;
        int worstSpan = -1;
        std::vector<double> spanErr(fit.knots.size(), 0.0);
        std::vector<int> spanCount(fit.knots.size(), 0);
        double basis[kMaxDegree + 1];
        for (size_t k = 0; k < params.size(); ++k) {
            const int span = findSpan(p, fit.knots, params[k]);
            basisFunctions(span, params[k], p, fit.knots, basis);
            Pt<Dim> c = Pt<Dim>::Zero();
            double W = 0.0;
            for (int j = 0; j <= p; ++j) {
                const double bw = basis[j] * (rational ? w[span - p + j] : 1.0);
                c += bw * local[span - p + j];
                W += bw;
            }
            c /= W;
            const double err = (c - target[k]).norm();
            worst = std::max(worst, err);
            spanErr[span] += err * err;
            ++spanCount[span];
        }
        double spanWorst = 0.0;
        for (size_t i = 0; i < spanErr.size(); ++i) {
            if (spanCount[i] >= kSamplesPerKnotMin && spanErr[i] > spanWorst) {
                spanWorst = spanErr[i];
                worstSpan = static_cast<int>(i);
            }
        }
        if (worst <= tolerance || s >= maxInterior || worstSpan < 0) {
            e.knots = std::move(Un);
            for (int i = 0; i < L0; ++i) e.points.push_back(cartesian<Dim>(P[i]));
            e.points.insert(e.points.end(), local.begin(), local.end());
            for (size_t i = ibOld; i < P.size(); ++i) e.points.push_back(cartesian<Dim>(P[i]));
            if (rational) {
                for (int i = 0; i < L0; ++i) e.weights.push_back(P[i][Dim]);
                e.weights.insert(e.weights.end(), w.begin(), w.end());
                for (size_t i = ibOld; i < P.size(); ++i) e.weights.push_back(P[i][Dim]);
            }
            e.localFirst = L0;
            e.localLast = L1;
            e.error = worst;
            return e;
        }
        // Alg. 1-2 reduces to inserting t* = (t_i + t_{i+1})/2: the pinned points are recomputed
        // from the blossom on the next pass, which is what eqs. 1-2 track incrementally.
        const double tStar = 0.5 * (fit.knots[worstSpan] + fit.knots[worstSpan + 1]);
        interior.insert(std::upper_bound(interior.begin(), interior.end(), tStar), tStar);
    }
}

}  // namespace

template <int Dim>
BSplineCurve<Dim> oversketchLocalC2(const BSplineCurve<Dim>& input, const StrokeOnCurve<Dim>& st,
                                    const OversketchOptions& o, std::pair<double, double>& span, double& maxError)
{
    const BSplineCurve<Dim> curve = input.isClosed() ? input : input.clamped();
    const int p = curve.degree();
    const double tol = fitTolerance(o, st.length);
    const CurveLengths<Dim> lengths(curve);

    // Closed curves with few spans: rounding [u_ps, u_pe] out to knots may span a whole period, or
    // the edit's support may not fit inside one; exact knot insertion (everywhere, or outside the
    // edit) makes the knots denser and the attempt is repeated.
    constexpr int kMaxRefinements = 8;
    BSplineCurve<Dim> c = curve;
    for (int attempt = 0;; ++attempt) {
        const Breaks br = breakPoints(c, lengths, st, o);
        span = {br.tk, br.tl};
        if (br.tooWide) {
            if (attempt >= kMaxRefinements) {
                throw GeometryError("stroke: the over-sketch with its transitions covers the whole closed curve");
            }
            c = refineOutside(c, {br.tk, br.tk}, 1);
            continue;
        }
        KnotVector U;
        std::vector<Hp<Dim>> P;
        auto homogeneous = [&](const ControlMatrix& rows) {
            for (Eigen::Index i = 0; i < rows.rows(); ++i) {
                Hp<Dim> h = Hp<Dim>::Ones();
                h.head(rows.cols()) = rows.row(i).transpose();
                P.push_back(h);
            }
        };
        if (c.isClosed()) {
            // Two periods each side: [t_k, t_l] lies within one period of [a - T, a + 2T] (breakPoints
            // checks t_l - t_k < T) and the pinned points reach p spans further.
            const PeriodicWindow w = periodicExtension(p, c.knots(), c.homogeneous(), 2);
            U = w.knots;
            homogeneous(w.points);
        } else {
            U = c.knots();
            homogeneous(c.homogeneous());
        }
        const Target<Dim> tgt = buildTarget(c, lengths, st, br);
        const Edit<Dim> e =
            localApproximation<Dim>(p, U, P, c.isRational(), br.tk, br.tl, br.leftFree, br.rightFree, tgt.params,
                                    tgt.points, tol);
        maxError = e.error;
        if (!c.isClosed()) return BSplineCurve<Dim>(p, e.knots, e.points, e.weights);

        // Closed: read one period [A, A + T] off the edited window such that no changed point's
        // support crosses its ends (then the wrapped points are unchanged copies and repeat).
        const int n0 = c.pointCount() - p;
        const int nNew = n0 + static_cast<int>(e.knots.size() - U.size());
        const int sigma = e.localLast + p + 1;
        const int iA = sigma - nNew;
        if (iA >= p && iA <= e.localFirst && sigma + p < static_cast<int>(e.knots.size())) {
            KnotVector k(e.knots.begin() + iA - p, e.knots.begin() + sigma + p + 1);
            std::vector<Pt<Dim>> q(e.points.begin() + iA - p, e.points.begin() + sigma);
            std::vector<double> w;
            if (!e.weights.empty()) w.assign(e.weights.begin() + iA - p, e.weights.begin() + sigma);
            return BSplineCurve<Dim>(p, std::move(k), std::move(q), std::move(w), true);
        }
        if (attempt >= kMaxRefinements) {
            throw GeometryError("stroke: the over-sketch covers (almost) the whole closed curve");
        }
        c = refineOutside(c, span, 1);
    }
}

template BSplineCurve<2> oversketchLocalC2<2>(const BSplineCurve<2>&, const StrokeOnCurve<2>&, const OversketchOptions&,
                                              std::pair<double, double>&, double&);
template BSplineCurve<3> oversketchLocalC2<3>(const BSplineCurve<3>&, const StrokeOnCurve<3>&, const OversketchOptions&,
                                              std::pair<double, double>&, double&);

}  // namespace sculptline::solvers::editing::detail
