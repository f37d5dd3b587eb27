// Given the numerical building blocks, then they agree with reference computations.
#include "solvers/bspline/basis.h"
#include "solvers/stroke/banded_cholesky.h"
#include "solvers/stroke/dynamic_sampling.h"
#include "solvers/stroke/features.h"
#include "solvers/stroke/lsq_fit.h"
#include "solvers/stroke/primitive_fit.h"
#include "solvers/stroke/spline_work.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

namespace sculptline::stroketest {
namespace {

using namespace solvers::stroke;

TEST(BandedCholesky, GivenRandomSpdBandMatrix_WhenSolved_ThenMatchesDenseLlt)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uni(-1, 1);
    const int n = 40, w = 3;
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
    BandMatrix band(n, w);
    for (int i = 0; i < n; ++i) {
        for (int j = std::max(0, i - w); j < i; ++j) {
            const double v = uni(rng);
            dense(i, j) = dense(j, i) = v;
            band.at(i, j) = v;
        }
        dense(i, i) = band.at(i, i) = 8.0 + uni(rng);  // diagonally dominant: SPD
    }
    Eigen::MatrixXd b = Eigen::MatrixXd::Random(n, 3);
    const Eigen::MatrixXd expected = dense.llt().solve(b);

    ASSERT_TRUE(band.factor());
    band.solveInPlace(b);

    EXPECT_LE((b - expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(BandedCholesky, GivenIndefiniteMatrix_ThenFactorReportsFailure)
{
    BandMatrix band(3, 1);
    band.at(0, 0) = 1;
    band.at(1, 0) = 2;
    band.at(1, 1) = 1;
    band.at(2, 2) = 1;
    EXPECT_FALSE(band.factor());
}

// The periodic least squares' solver (solveClosed): a cyclic band of half-bandwidth 3 at every size a
// loop can have, from the smallest (5 unknowns; 4, the least the border leaves a block for) where
// the cyclic band fills the whole matrix, to sizes beyond the dense path it replaced (96).
TEST(CyclicBandedCholesky, GivenRandomSpdCyclicBandMatrices_WhenSolved_ThenMatchDenseLlt)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uni(-1, 1);
    const int w = CyclicBandMatrix::kBandwidth;
    for (const int n : {4, 5, 6, 7, 8, 13, 40, 200}) {
        SCOPED_TRACE(n);
        Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
        CyclicBandMatrix cyclic;
        cyclic.reset(n);
        // Entries within w of the diagonal modulo n, each pair once (small n: some pairs are
        // within w both ways round; they are one entry).
        for (int i = 0; i < n; ++i) {
            for (int d = 1; d <= w; ++d) {
                const int j = (i + d) % n;
                if (dense(i, j) != 0.0 || i == j) continue;
                const double v = uni(rng);
                dense(i, j) = dense(j, i) = v;
                cyclic.addLower(std::max(i, j), std::min(i, j), v);
            }
        }
        for (int i = 0; i < n; ++i) {
            dense(i, i) = 2.0 * w + 2.0 + uni(rng);  // diagonally dominant: SPD
            cyclic.addLower(i, i, dense(i, i));
        }
        std::vector<Eigen::Vector3d> b(static_cast<size_t>(n));
        Eigen::MatrixXd rhs(n, 3);
        for (int i = 0; i < n; ++i) {
            b[static_cast<size_t>(i)] = Eigen::Vector3d(uni(rng), uni(rng), uni(rng));
            rhs.row(i) = b[static_cast<size_t>(i)].transpose();
        }
        const Eigen::MatrixXd expected = dense.llt().solve(rhs);

        ASSERT_TRUE(cyclic.factor());
        cyclic.solveInPlace(b);

        // (Condition number below 3 by the diagonal dominance: agreement to round-off.)
        double worst = 0.0;
        for (int i = 0; i < n; ++i)
            worst = std::max(worst, (b[static_cast<size_t>(i)] - expected.row(i).transpose()).cwiseAbs().maxCoeff());
        EXPECT_LE(worst, 1e-12);
    }
}

TEST(CyclicBandedCholesky, GivenIndefiniteMatrices_ThenFactorReportsFailure)
{
    // The leading band block indefinite, then only the border's Schur complement.
    CyclicBandMatrix leading;
    leading.reset(8);
    for (int i = 0; i < 8; ++i) leading.addLower(i, i, 1.0);
    leading.addLower(1, 0, 2.0);
    EXPECT_FALSE(leading.factor());
    CyclicBandMatrix border;
    border.reset(8);
    for (int i = 0; i < 8; ++i) border.addLower(i, i, 1.0);
    border.addLower(7, 0, 2.0);  // a wrapped entry: (0, 7) are neighbours modulo 8
    EXPECT_FALSE(border.factor());
}

// A closed curve's samples move between their neighbours, the first and last a period apart. When
// the last sample was clamped to the first's parameter plus one, (u_0 + 1) - 1 rounds above u_0:
// with the second sample at u_0 too, the first sample's range [u_last - 1, u_1] came out inverted
// and std::clamp asserted in the sanitizer build (a sparse loop, FitTolerance.GivenSparseLoops_*).
TEST(SeamRange, GivenNeighboursThatMeetAcrossTheSeam_ThenTheRangeIsOnePointNotInverted)
{
    const double u0 = 0.0044240393791330317;  // the failing loop's parameters, 16 samples
    const std::vector<double> u = {u0, u0, 0.3, 0.7, u0 + 1.0};
    ASSERT_GT(u.back() - 1.0, u[1]) << "the round-off this guards against";
    const auto [lo, hi] = detail::neighbourRange(u, 0);
    EXPECT_EQ(lo, u.back() - 1.0);
    EXPECT_EQ(hi, lo);
    // Elsewhere the range is the neighbours' parameters.
    const auto [lo2, hi2] = detail::neighbourRange(u, 2);
    EXPECT_EQ(lo2, u0);
    EXPECT_EQ(hi2, 0.7);
    const auto [lo4, hi4] = detail::neighbourRange(u, 4);
    EXPECT_EQ(lo4, 0.7);
    EXPECT_EQ(hi4, u0 + 1.0);
}

TEST(DynamicThreshold, GivenSpeedRatios_ThenEquations42And43AsRead)
{
    const double unit = 2.0;
    // Slow (eq. 4-2): round(2 S_avg / S_i + 0.5) ticks of r = S_i / S_avg units each.
    EXPECT_DOUBLE_EQ(samplingThreshold(0.1, 1.0, unit), 21 * 0.1 * unit);  // round(20.5) = 21 ticks
    EXPECT_DOUBLE_EQ(samplingThreshold(0.5, 1.0, unit), 5 * 0.5 * unit);   // round(4.5) = 5 ticks
    EXPECT_DOUBLE_EQ(samplingThreshold(0.9, 1.0, unit), 3 * 0.9 * unit);   // round(2.72) = 3 ticks
    // Fast (eq. 4-3): 7 S_avg / S_i ticks of r units = 7 units whatever the speed.
    EXPECT_DOUBLE_EQ(samplingThreshold(1.0, 1.0, unit), 7 * unit);
    EXPECT_DOUBLE_EQ(samplingThreshold(3.0, 1.5, unit), 7 * unit);
    // A stopped pen (S_i = 0) still gives a finite spacing, never below 2 units.
    EXPECT_GE(samplingThreshold(0.0, 1.0, unit), 2 * unit);
    EXPECT_TRUE(std::isfinite(samplingThreshold(0.0, 1.0, unit)));
}

TEST(FastAtan2, GivenAllDirections_ThenWithin1e5OfLibm)
{
    constexpr double kAngleTolerance = 1e-5;  // the documented bound
    double worst = 0;
    for (int i = 0; i < 100000; ++i) {
        const double a = -3.14159265358979 + 6.28318530717958 * i / 100000.0;
        for (double r : {1e-3, 1.0, 1e4}) {
            const double y = r * std::sin(a), x = r * std::cos(a);
            worst = std::max(worst, std::abs(fastAtan2(y, x) - std::atan2(y, x)));
        }
    }
    EXPECT_LE(worst, kAngleTolerance);
    EXPECT_EQ(fastAtan2(0.0, 0.0), 0.0);
}

TEST(EllipseFit, GivenNoisyPointsOfAnElongatedEllipse_ThenParametersAndWindowedResidualMatchBruteForce)
{
    // A 6:1 ellipse rotated by 0.4 rad; jitter of 1 % of the minor axis.
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0, 0.1);
    const Point2 c(5, -2);
    const double a = 60, b = 10, th = 0.4;
    const Point2 ua(std::cos(th), std::sin(th)), ub(-ua.y(), ua.x());
    std::vector<Point2> pts;
    for (int i = 0; i < 300; ++i) {
        const double t = 2 * 3.14159265358979 * i / 300;
        pts.push_back(c + a * std::cos(t) * ua + b * std::sin(t) * ub + Point2(noise(rng), noise(rng)));
    }

    const EllipseFit f = fitEllipse(pts);

    ASSERT_TRUE(f.valid);
    EXPECT_NEAR(f.a, a, 0.2);
    EXPECT_NEAR(f.b, b, 0.2);
    EXPECT_NEAR(std::abs(std::cos(f.angle - th)), 1.0, 1e-4);
    std::vector<Point2> poly;
    for (int i = 0; i < 720; ++i) {
        const double t = 2 * 3.14159265358979323846 * i / 720;
        const Point2 u(std::cos(f.angle), std::sin(f.angle)), v(-u.y(), u.x());
        poly.push_back(f.center + f.a * std::cos(t) * u + f.b * std::sin(t) * v);
    }
    EXPECT_NEAR(f.maxResidual, polylineResidual(pts, poly, true), 1e-9);
}

// SplineFitOptions::averagedStopWhenWithin and averagedResume: a fixed count whose samples fit
// before its last correction stops there; resumed from that state it ends with the uninterrupted
// fit's curve, to the bit (the search in fitStroke takes the resumed curve).
TEST(LeastSquaresSpline, GivenAnAveragedFitStoppedOnceItsSamplesFit_WhenResumed_ThenTheUninterruptedFitToTheBit)
{
    // A wavy open curve, 400 points with a little noise, chord parameters, every 4th a row.
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0.0, 0.05);
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 400; ++i) {
        const double t = i / 399.0;
        pts.emplace_back(100 * t + noise(rng), 20 * std::sin(9 * t) + 8 * std::sin(23 * t) + noise(rng), 0.0);
    }
    std::vector<double> chord(pts.size(), 0.0);
    for (size_t i = 1; i < pts.size(); ++i) chord[i] = chord[i - 1] + (pts[i] - pts[i - 1]).norm();
    for (double& c : chord) c /= chord.back();
    SplineFitInput in;
    in.points = &pts;
    in.chord = &chord;
    for (int i = 0; i < 400; i += 4) in.samples.push_back(i);
    in.samples.push_back(399);
    SplineFitOptions o;
    o.tolerance = 0.5;
    o.knotPlacement = KnotPlacement::Averaged;
    o.averagedCorrections = 8;

    // The counts from 8 up: the first whose samples fit before the last correction stops early.
    int stoppedAt = 0;
    for (int count = 8; count <= 40 && stoppedAt == 0; ++count) {
        o.averagedControlPoints = count;
        o.averagedStopWhenWithin = true;
        const SplineFitResult stopped = fitCubicSpline(in, o);
        if (!stopped.correction.stopped) continue;
        stoppedAt = count;
        EXPECT_LE(stopped.maxError, o.tolerance);
        EXPECT_LT(stopped.correction.done, o.averagedCorrections);
        EXPECT_EQ(stopped.correction.parameters.size(), in.samples.size());

        o.averagedStopWhenWithin = false;
        o.averagedResume = &stopped.correction;
        const SplineFitResult resumed = fitCubicSpline(in, o);
        o.averagedResume = nullptr;
        const SplineFitResult whole = fitCubicSpline(in, o);

        EXPECT_FALSE(resumed.correction.stopped);
        ASSERT_EQ(resumed.knots.size(), whole.knots.size());
        for (size_t k = 0; k < whole.knots.size(); ++k) EXPECT_EQ(resumed.knots[k], whole.knots[k]) << k;
        ASSERT_EQ(resumed.points.size(), whole.points.size());
        for (size_t k = 0; k < whole.points.size(); ++k) EXPECT_EQ(resumed.points[k], whole.points[k]) << k;
        EXPECT_EQ(resumed.maxError, whole.maxError);
        // And the stopped curve is not already that curve: the corrections left changed it.
        EXPECT_NE(stopped.points, whole.points);
    }
    EXPECT_GT(stoppedAt, 0) << "no count stopped early: the test exercises nothing";
}

// The weighted least squares (detail::solve with weights, the minimax rounds' solve) is the
// weighted problem's minimum: the residuals are orthogonal to every free basis function in the
// weighted inner product (sum_k w_k N_j(u_k) (C(u_k) - x_k) = 0; no fairing term), open and
// periodic; and the weights change the curve (weights of one give the unweighted solve, to the bit).
TEST(LeastSquaresSpline, GivenWeights_WhenSolved_ThenTheWeightedNormalEquationsHold)
{
    using namespace solvers::stroke::detail;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> weight(0.05, 3.0);
    std::normal_distribution<double> noise(0.0, 0.3);
    for (const bool closed : {false, true}) {
        std::vector<Eigen::Vector3d> pts;
        std::vector<double> u;
        std::vector<int> S;
        const int m = 120;
        for (int i = 0; i < m; ++i) {
            const double t = closed ? i / double(m) : i / double(m - 1);
            pts.emplace_back(40 * std::cos(6.283185307179586 * t) + noise(rng),
                             25 * std::sin(6.283185307179586 * t) + noise(rng), 0.0);
            u.push_back(t);
            S.push_back(i);
        }
        std::vector<double> w(m);
        for (double& v : w) v = weight(rng);
        Spline s, ones, plain;
        s.closed = ones.closed = plain.closed = closed;
        s.breaks = closed ? std::vector<double>{0.0, 0.13, 0.27, 0.4, 0.55, 0.7, 0.84}
                          : std::vector<double>{0.0, 0.13, 0.27, 0.4, 0.55, 0.7, 0.84, 1.0};
        ones.breaks = plain.breaks = s.breaks;
        solve(s, pts, S, u, 0.0, &w);
        const std::vector<double> unit(m, 1.0);
        solve(ones, pts, S, u, 0.0, &unit);
        solve(plain, pts, S, u, 0.0);
        EXPECT_EQ(ones.ctrl, plain.ctrl) << "closed " << closed;
        double moved = 0.0;
        for (size_t i = 0; i < s.ctrl.size(); ++i) moved = std::max(moved, (s.ctrl[i] - plain.ctrl[i]).norm());
        EXPECT_GT(moved, 0.01) << "closed " << closed << ": the weights changed nothing";

        // The weighted normal equations, from the basis evaluated independently of the solve.
        const int n = s.unknowns();
        std::vector<Eigen::Vector3d> grad(static_cast<size_t>(n), Eigen::Vector3d::Zero());
        double scale = 0.0;
        const int first = closed ? 0 : 1, last = closed ? m : m - 1;  // (open: the ends are P_0, P_n)
        for (int k = first; k < last; ++k) {
            const double uk = s.wrap(u[k]);
            const int span = solvers::findSpan(kDegree, s.knots, uk);
            const auto b = solvers::evaluateBasis<kDegree, 0>(s.knots, span, uk);
            Eigen::Vector3d c = Eigen::Vector3d::Zero();
            for (int q = 0; q <= kDegree; ++q) c += b.d[0][q] * s.ctrl[span - kDegree + q];
            const Eigen::Vector3d r = c - pts[k];
            for (int q = 0; q <= kDegree; ++q) {
                const int j = closed ? (span - kDegree + q) % n : span - kDegree + q;
                grad[static_cast<size_t>(j)] += w[k] * b.d[0][q] * r;
            }
            scale += w[k] * r.norm();
        }
        // Round-off of sums of ~100 terms of the residuals' size, relative to their weighted sum.
        constexpr double kOrthogonality = 1e-10;
        for (int j = closed ? 0 : 1; j < (closed ? n : n - 1); ++j)
            EXPECT_LE(grad[static_cast<size_t>(j)].norm(), kOrthogonality * scale)
                << "closed " << closed << " basis " << j;
    }
}

// The fewest averaged counts from 6 up to `last` within o's tolerance, fitted with `plain` and with
// `better` applied to o: {plain's, better's} (0: none). At every count tried, the better fit's
// largest distance is no larger (its best trial or round is kept).
template <class Plain, class Better>
std::pair<int, int> fewestWithin(const SplineFitInput& in, SplineFitOptions o, int last, Plain plain, Better better)
{
    int a = 0, b = 0;
    for (int count = 6; count <= last && (a == 0 || b == 0); ++count) {
        o.averagedControlPoints = count;
        plain(o);
        const SplineFitResult p = fitCubicSpline(in, o);
        better(o);
        const SplineFitResult q = fitCubicSpline(in, o);
        EXPECT_LE(q.maxError, p.maxError) << count;
        if (p.maxError <= o.tolerance && a == 0) a = count;
        if (q.maxError <= o.tolerance && b == 0) b = count;
    }
    return {a, b};
}

// SplineFitOptions::minimaxRounds: at a fixed averaged count, the minimax rounds never leave a
// larger maximum distance than the least squares (the best round is kept), and they bring counts
// within the tolerance that the least squares misses: a circle of 60 points rounded to the pixel
// (the noise of the $1 logs) at a tolerance of 0.45 pixel.
TEST(LeastSquaresSpline, GivenPixelNoise_WhenMinimaxRoundsFollowTheCorrections_ThenTheLargestDistanceFallsWithin)
{
    std::vector<Eigen::Vector3d> pts;
    const int m = 60;
    for (int i = 0; i < m; ++i) {
        const double t = 6.283185307179586 * i / m;
        pts.emplace_back(std::round(30 * std::cos(t) + 0.3 * std::sin(3 * t)), std::round(22 * std::sin(t)), 0.0);
    }
    std::vector<double> chord(m, 0.0);
    double length = 0.0;
    for (int i = 1; i <= m; ++i) {
        length += (pts[i % m] - pts[i - 1]).norm();
        if (i < m) chord[i] = length;
    }
    for (double& c : chord) c /= length;
    SplineFitInput in;
    in.points = &pts;
    in.chord = &chord;
    in.closed = true;
    for (int i = 0; i < m; ++i) in.samples.push_back(i);
    SplineFitOptions o;
    o.tolerance = 0.45;
    o.knotPlacement = KnotPlacement::Averaged;
    o.averagedCorrections = 8;
    const auto [leastSquares, minimax] = fewestWithin(
        in, o, 40, [](SplineFitOptions& v) { v.minimaxRounds = 0; }, [](SplineFitOptions& v) { v.minimaxRounds = 10; });
    std::printf("fewest control points within %.2f: least squares %d, minimax rounds %d\n", o.tolerance, leastSquares,
                minimax);
    ASSERT_GT(minimax, 0);
    ASSERT_GT(leastSquares, 0);
    EXPECT_LT(minimax, leastSquares);
}

// A ripple on a third of an open curve (the detail in one part): 300 points, chord parameters,
// every point a row.
struct RippleInput {
    std::vector<Eigen::Vector3d> pts;
    std::vector<double> chord;
    SplineFitInput in;  // (points to the two above: not copyable)
    RippleInput(const RippleInput&) = delete;
    RippleInput& operator=(const RippleInput&) = delete;
    RippleInput()
    {
        const int m = 300;
        for (int i = 0; i < m; ++i) {
            const double t = i / double(m - 1);
            const double ripple = t > 0.6 && t < 0.9 ? 2.0 * std::sin(40 * (t - 0.6)) : 0.0;
            pts.emplace_back(100 * t, 10 * std::sin(3 * t) + ripple, 0.0);
        }
        chord.assign(m, 0.0);
        for (int i = 1; i < m; ++i) chord[i] = chord[i - 1] + (pts[i] - pts[i - 1]).norm();
        for (double& c : chord) c /= chord.back();
        in.points = &pts;
        in.chord = &chord;
        for (int i = 0; i < m; ++i) in.samples.push_back(i);
    }
};

// The averaged fit RippleInput's tests make: a twentieth of a unit, three corrections, ten rounds.
SplineFitOptions rippleOptions()
{
    SplineFitOptions o;
    o.tolerance = 0.05;
    o.knotPlacement = KnotPlacement::Averaged;
    o.averagedCorrections = 3;
    o.minimaxRounds = 10;
    return o;
}

// SplineFitOptions::equidistributions: where the detail is in one part of a stroke (a ripple on a
// third of an open curve), breaks averaged over the samples spread the control points evenly; moved
// to equidistribute the spans' largest distances they gather where the error is, and a count the
// averaged breaks miss fits. The best trial is kept, so the error never grows.
TEST(LeastSquaresSpline, GivenDetailInOnePart_WhenBreaksAreEquidistributed_ThenFewerControlPointsFit)
{
    const RippleInput r;
    SplineFitOptions o = rippleOptions();
    const auto [averaged, moved] = fewestWithin(
        r.in, o, 150, [](SplineFitOptions& v) { v.equidistributions = 0; },
        [](SplineFitOptions& v) { v.equidistributions = 3; });
    std::printf("fewest control points within %.2f: averaged breaks %d, equidistributed %d\n", o.tolerance, averaged,
                moved);
    ASSERT_GT(moved, 0);
    ASSERT_GT(averaged, 0);
    EXPECT_LT(moved, averaged);
}

// SplineFitOptions::insertedTrials: a count whose trial on averaged breaks misses is tried on
// FITPACK's knots (a knot at the middle sample of the span whose squared distances sum the most,
// one per least squares), which gather where the detail is: a count the averaged breaks miss fits,
// the error never grows (the better trial is kept), and a curve that took FITPACK's knots has its
// interior knots at samples' parameters.
TEST(LeastSquaresSpline, GivenDetailInOnePart_WhenFitpackKnotsAreTried_ThenFewerControlPointsFit)
{
    const RippleInput r;
    SplineFitOptions o = rippleOptions();
    // (Counts up to 40 only: the averaged breaks need 120, measured up to 150; the sanitizer build
    // takes seconds for them.)
    const auto [averaged, inserted] = fewestWithin(
        r.in, o, 40, [](SplineFitOptions& v) { v.insertedTrials = false; },
        [](SplineFitOptions& v) { v.insertedTrials = true; });
    std::printf(
        "fewest control points within %.2f up to 40: averaged breaks %d (0: none), FITPACK's where they "
        "miss %d\n",
        o.tolerance, averaged, inserted);
    ASSERT_GT(inserted, 0);
    EXPECT_TRUE(averaged == 0 || inserted < averaged);

    o.insertedTrials = true;
    o.averagedControlPoints = inserted;
    const SplineFitResult f = fitCubicSpline(r.in, o);
    ASSERT_LE(f.maxError, o.tolerance);
    for (size_t k = 4; k + 4 < f.knots.size(); ++k)
        EXPECT_TRUE(std::binary_search(r.chord.begin(), r.chord.end(), f.knots[k])) << "knot " << f.knots[k];
}

// SplineFitOptions::trialCache: trials on one input keep FITPACK's knots and each count's trial for
// the trials after them. Asked in any order (counts up and down, again, after trials on another
// input), each count's curve is the one a fit without the cache makes, to the bit.
TEST(LeastSquaresSpline, GivenATrialCache_WhenCountsAreAskedInAnyOrder_ThenEachCurveIsTheUncachedOneToTheBit)
{
    const RippleInput r;
    SplineFitInput other = r.in;  // (another input: every other row)
    other.samples.clear();
    for (int i = 0; i < 300; i += 2) other.samples.push_back(i);
    other.samples.push_back(299);
    SplineFitOptions o = rippleOptions();
    o.insertedTrials = true;
    o.equidistributions = 2;
    AveragedTrialCache cache;
    int differ = 0;  // (counts where FITPACK's knots were taken: the cache's insertion was used)
    const std::vector<std::pair<const SplineFitInput*, int>> asked = {
        {&r.in, 40},  {&r.in, 20},  {&r.in, 30}, {&r.in, 20}, {&r.in, 55}, {&other, 12},
        {&other, 20}, {&other, 12}, {&r.in, 40}, {&r.in, 12}, {&r.in, 40}};
    for (const auto& [in, count] : asked) {
        {
            o.averagedControlPoints = count;
            o.trialCache = nullptr;
            const SplineFitResult fresh = fitCubicSpline(*in, o);
            o.trialCache = &cache;
            const SplineFitResult cached = fitCubicSpline(*in, o);
            o.insertedTrials = false;
            o.trialCache = nullptr;
            differ += fitCubicSpline(*in, o).knots != fresh.knots;
            o.insertedTrials = true;
            EXPECT_EQ(cached.knots, fresh.knots) << count;
            EXPECT_EQ(cached.points, fresh.points) << count;
            EXPECT_EQ(cached.maxError, fresh.maxError) << count;
        }
    }
    EXPECT_GT(differ, 0) << "FITPACK's knots were never taken: the cache's insertion is not exercised";
}

TEST(LeastSquaresSpline, GivenSamplesOfACubic_ThenReproducedExactlyWithOneSpan)
{
    // A single cubic Bezier segment is in the spline space: the fit must reproduce it.
    std::vector<Eigen::Vector3d> pts;
    std::vector<double> chord;
    SplineFitInput in;
    for (int i = 0; i <= 50; ++i) {
        const double t = i / 50.0;
        pts.emplace_back(t, t * t * t - t, 0.5 * t * t);
        chord.push_back(t);
        in.samples.push_back(i);
    }
    in.points = &pts;
    in.chord = &chord;
    SplineFitOptions o;
    o.tolerance = 1e-6;
    o.fairing = 0.0;  // no bias: the exact answer is in the space

    const SplineFitResult r = fitCubicSpline(in, o);

    EXPECT_EQ(r.points.size(), 4u);
    EXPECT_LE(r.maxError, 1e-10);
    EXPECT_TRUE(r.converged);
}

// Knot removal in the least squares (SplineFitOptions::removal = AllKnots) re-sums only the six
// spans around the removed break: the solution must be the one a solve from scratch gives, for
// breaks near either clamped end as well as inside.
TEST(SpanSums, GivenABreakRemoved_WhenOnlyTheSpansAroundItAreSummedAgain_ThenSameSolutionAsAFullSolve)
{
    std::vector<Eigen::Vector3d> pts;
    std::vector<int> S;
    std::vector<double> u;
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.01);
    for (int i = 0; i <= 300; ++i) {
        const double t = i / 300.0;
        pts.emplace_back(std::cos(5 * t) + noise(rng), std::sin(3 * t) + noise(rng), t * t);
        S.push_back(i);
        u.push_back(t);
    }
    detail::Spline s;
    for (int i = 0; i <= 12; ++i) s.breaks.push_back(i / 12.0 + (i > 0 && i < 12 ? 0.01 * std::sin(i) : 0.0));
    detail::solve(s, pts, S, u, 1e-6);
    std::vector<detail::SpanSums> sums;
    detail::spanSums(s, pts, S, u, 0, s.spanCount() - 1, sums);
    for (int r = 1; r + 1 < static_cast<int>(s.breaks.size()); ++r) {
        detail::Spline incremental = s, fresh = s;
        std::vector<detail::SpanSums> out;
        detail::sumsWithoutBreak(incremental, r, pts, S, u, sums, out);
        detail::solveOpenFromSums(incremental, pts, S, out, 1e-6);
        fresh.breaks.erase(fresh.breaks.begin() + r);
        detail::solve(fresh, pts, S, u, 1e-6);
        ASSERT_EQ(incremental.ctrl.size(), fresh.ctrl.size()) << r;
        for (size_t i = 0; i < fresh.ctrl.size(); ++i) {
            // Same sums in the same order: equal to round-off (in practice bit for bit).
            EXPECT_LE((incremental.ctrl[i] - fresh.ctrl[i]).norm(), 1e-12) << "break " << r << ", point " << i;
        }
    }
}

// Between insertion rounds the spans untouched by the new knots keep their sums: the solution must
// be the one a solve from scratch gives, whatever breaks were inserted (ends included).
TEST(SpanSums, GivenKnotsInserted_WhenOnlyTheChangedSpansAreSummedAgain_ThenSameSolutionAsAFullSolve)
{
    std::vector<Eigen::Vector3d> pts;
    std::vector<int> S;
    std::vector<double> u;
    for (int i = 0; i <= 200; ++i) {
        const double t = i / 200.0;
        pts.emplace_back(std::cos(4 * t), std::sin(7 * t), t);
        S.push_back(i);
        u.push_back(t);
    }
    detail::Spline s;
    s.breaks = {0.0, 0.2, 0.45, 0.7, 1.0};
    detail::solve(s, pts, S, u, 1e-6);
    std::vector<detail::SpanSums> sums;
    detail::spanSums(s, pts, S, u, 0, s.spanCount() - 1, sums);
    for (const std::vector<double>& inserted : {std::vector<double>{0.05}, {0.5}, {0.95}, {0.1, 0.3, 0.85}}) {
        detail::Spline incremental = s;
        incremental.breaks.insert(incremental.breaks.end(), inserted.begin(), inserted.end());
        std::sort(incremental.breaks.begin(), incremental.breaks.end());
        detail::Spline fresh = incremental;
        incremental.makeKnots();
        std::vector<detail::SpanSums> out;
        detail::updateSpanSums(incremental, s.breaks, sums, pts, S, u, out);
        detail::solveOpenFromSums(incremental, pts, S, out, 1e-6);
        detail::solve(fresh, pts, S, u, 1e-6);
        ASSERT_EQ(incremental.ctrl.size(), fresh.ctrl.size());
        for (size_t i = 0; i < fresh.ctrl.size(); ++i)
            EXPECT_LE((incremental.ctrl[i] - fresh.ctrl[i]).norm(), 1e-12) << "first inserted " << inserted.front() << ", point " << i;
    }
}

}  // namespace
}  // namespace sculptline::stroketest
