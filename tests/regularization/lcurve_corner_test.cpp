// The L-curve corner on Hansen's test problems (Regularization Tools: shaw, phillips, baart, heat,
// foxgood; n = 64, white noise from fixed seeds at two levels): the corner's error ‖x_k − x‖ must be
// within kErrorRatio of the best truncation's. Both corner methods, TSVD and MTSVD. Prints the table
// that README "Regularization" quotes. Given / When / Then.
#include "solvers/regularization/lcurve_corner.h"
#include "solvers/regularization/mtsvd.h"
#include "solvers/regularization/test_problems.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace sculptline::solvers::regularization;

namespace {

constexpr int kSize = 64;
constexpr double kErrorRatio = 1.5;  // the corner's error over the best k's
const std::vector<double> kNoiseLevels = {1e-3, 1e-2};
// Noise that dominates ‖x‖ at the least regularized end (README "Which corner method"): evaluation
// seeds only, never used for tuning.
const std::vector<double> kHighNoiseLevels = {5e-2, 1e-1};
// The corner methods' constants (e.g. the knot-removal turn window) were chosen looking at the tuning
// seeds only; the evaluation seeds, never looked at while tuning, give the numbers README reports.
const std::vector<unsigned> kTuningSeeds = {1, 2, 3};
const std::vector<unsigned> kEvaluationSeeds = {11, 12, 13, 14, 15};
// Cases where the corner's error is within kErrorRatio of the best, as measured (README "Which corner
// method"): the 1.5× rule does not hold on every case — phillips' and heat's L-curves at n = 64 turn
// where η = ‖x_k‖ first notices the noise, well after the best k — so these counts guard against
// regressions. Index: [set: tuning, evaluation, high noise][mtsvd][pruning]; 30, 50 and 50 cases.
constexpr int kMinPassed[3][2][2] = {{{16, 12}, {12, 14}}, {{29, 22}, {21, 21}}, {{39, 43}, {26, 22}}};

struct Outcome {
    int k, bestK;
    double error, bestError;
};

Outcome judge(const TestProblem& p, const Eigen::VectorXd& b, CornerMethod method, bool modified)
{
    const CachedSvd svd(p.a);
    const ProjectedRhs rhs = projectRhs(svd, b);
    const MtsvdSolver mtsvd(svd, secondDifferences(kSize));
    const LCurve lc = modified ? mtsvd.lcurve(rhs) : tsvdLCurve(svd, rhs);
    auto error = [&](int k) {
        return ((modified ? mtsvd.solution(rhs, k) : tsvdSolution(svd, rhs, k)) - p.x).norm() / p.x.norm();
    };
    Outcome o{lcurveCorner(lc, method).k, 1, 0.0, std::numeric_limits<double>::infinity()};
    for (int k = 1; k <= svd.rank(); ++k) {
        const double e = error(k);
        if (e < o.bestError) o.bestError = e, o.bestK = k;
    }
    o.error = error(o.k);
    return o;
}

enum Set { Tuning, Evaluation, HighNoise };

void runTable(bool modified, Set set)
{
    const std::vector<unsigned>& seeds = set == Tuning ? kTuningSeeds : kEvaluationSeeds;
    const std::vector<double>& levels = set == HighNoise ? kHighNoiseLevels : kNoiseLevels;
    const char* label = set == Tuning ? "tuning" : set == Evaluation ? "evaluation" : "high-noise";
    int passed[2] = {0, 0}, total = 0;
    double worst[2] = {0.0, 0.0};
    std::printf("%s seeds\n", label);
    std::printf("%s | noise | seed | best k (error) | knot-removal k (error) | pruning k (error)\n",
                modified ? "MTSVD" : "TSVD");
    for (const TestProblem& p : hansenProblems(kSize)) {
        for (double level : levels) {
            for (unsigned seed : seeds) {
                const Eigen::VectorXd b = withNoise(p.b, level, seed);
                const Outcome a = judge(p, b, CornerMethod::KnotRemoval, modified);
                const Outcome h = judge(p, b, CornerMethod::AdaptivePruning, modified);
                std::printf("row %s %s | %-8s | %g | %u | %d (%.4f) | %d (%.4f) %s | %d (%.4f) %s\n", label,
                            modified ? "MTSVD" : "TSVD", p.name.c_str(), level, seed,
                            a.bestK, a.bestError, a.k, a.error, a.error <= kErrorRatio * a.bestError ? "ok" : "FAIL",
                            h.k, h.error, h.error <= kErrorRatio * h.bestError ? "ok" : "FAIL");
                ++total;
                passed[0] += a.error <= kErrorRatio * a.bestError;
                passed[1] += h.error <= kErrorRatio * h.bestError;
                worst[0] = std::max(worst[0], a.error / a.bestError);
                worst[1] = std::max(worst[1], h.error / h.bestError);
                // Where the rule holds on all 8 seeds of both sets (README "Which corner method"), it is
                // asserted case by case: TSVD, both methods, on baart and on foxgood at 1 %; MTSVD, both
                // methods, on baart at 1 %, and by pruning (its default) on phillips at 0.1 %.
                const bool tsvdHolds = set != HighNoise && !modified && (p.name == "baart" || (p.name == "foxgood" && level == 1e-2));
                const bool mtsvdHolds = set != HighNoise && modified && p.name == "baart" && level == 1e-2;
                if (tsvdHolds || mtsvdHolds) {
                    EXPECT_LE(a.error, kErrorRatio * a.bestError) << p.name << " " << level << " seed " << seed;
                }
                if (tsvdHolds || mtsvdHolds || (set != HighNoise && modified && p.name == "phillips" && level == 1e-3)) {
                    EXPECT_LE(h.error, kErrorRatio * h.bestError) << p.name << " " << level << " seed " << seed;
                }
            }
        }
    }
    std::printf("passed: knot-removal %d/%d (worst ratio %.2f), pruning %d/%d (worst ratio %.2f)\n", passed[0], total,
                worst[0], passed[1], total, worst[1]);
    EXPECT_GE(passed[0], kMinPassed[set][modified][0]) << label;
    EXPECT_GE(passed[1], kMinPassed[set][modified][1]) << label;
}

}  // namespace

TEST(LCurveCorner, GivenHansensProblems_WhenTsvdCornerChosen_ThenItsErrorIsNearTheBest)
{
    runTable(false, Tuning);
    runTable(false, Evaluation);
    runTable(false, HighNoise);
}

TEST(LCurveCorner, GivenHansensProblems_WhenMtsvdCornerChosen_ThenItsErrorIsNearTheBest)
{
    runTable(true, Tuning);
    runTable(true, Evaluation);
    runTable(true, HighNoise);
}

TEST(LCurveCorner, GivenAnIdealL_WhenCornerSought_ThenBothMethodsFindTheElbow)
{
    // Ten points along a horizontal leg, then ten up a vertical one: the elbow is k = 10.
    LCurve lc;
    lc.rho.resize(20);
    lc.eta.resize(20);
    for (int i = 0; i < 20; ++i) {
        lc.rho(i) = i < 10 ? std::pow(10.0, 2.0 - 0.2 * i) : std::pow(10.0, 0.2 - 0.002 * (i - 9));
        lc.eta(i) = i < 10 ? std::pow(10.0, 0.01 * i) : std::pow(10.0, 0.09 + 0.3 * (i - 9));
    }
    EXPECT_EQ(cornerByKnotRemoval(lc).k, 10);
    EXPECT_EQ(cornerByAdaptivePruning(lc).k, 10);
}

TEST(LCurveCorner, GivenTooFewOrBadPoints_WhenCornerSought_ThenTheFirstExactFitOrTheLastUsable)
{
    LCurve lc;
    // ρ = 0 at k = 2 (b fitted exactly there; the 0.5 after it is round-off gone wrong): k = 2.
    lc.rho = Eigen::Vector3d(1.0, 0.0, 0.5);
    lc.eta = Eigen::Vector3d(1.0, 2.0, 3.0);
    EXPECT_EQ(lcurveCorner(lc, CornerMethod::KnotRemoval).k, 2);
    EXPECT_EQ(lcurveCorner(lc, CornerMethod::AdaptivePruning).k, 2);
    // b fitted exactly from k = 2 on: that k; from k = 1 on: k = 1.
    lc.rho = Eigen::Vector3d(1.0, 0.0, 0.0);
    EXPECT_EQ(lcurveCorner(lc, CornerMethod::KnotRemoval).k, 2);
    lc.rho.setZero();
    EXPECT_EQ(lcurveCorner(lc, CornerMethod::KnotRemoval).k, 1);
    EXPECT_EQ(lcurveCorner(lc, CornerMethod::AdaptivePruning).k, 1);
    EXPECT_THROW(lcurveCorner(LCurve{}, CornerMethod::KnotRemoval), std::invalid_argument);
    EXPECT_THROW(lcurveCorner(LCurve{}, CornerMethod::AdaptivePruning), std::invalid_argument);
}

TEST(LCurveCorner, GivenALastPointAtARoundOffSingularValue_WhenCornerSought_ThenItIsSkipped)
{
    // Given an ideal L (elbow at k = 10) followed by one point whose σ is at round-off (5e-15 σ_1, as
    // heat's σ_62 at n = 64), where η jumps ten decades in one step.
    LCurve lc;
    lc.rho.resize(21);
    lc.eta.resize(21);
    lc.sigma.resize(21);
    for (int i = 0; i < 20; ++i) {
        lc.rho(i) = i < 10 ? std::pow(10.0, 2.0 - 0.2 * i) : std::pow(10.0, 0.2 - 0.002 * (i - 9));
        lc.eta(i) = i < 10 ? std::pow(10.0, 0.01 * i) : std::pow(10.0, 0.09 + 0.3 * (i - 9));
        lc.sigma(i) = std::pow(10.0, -0.5 * i);
    }
    lc.rho(20) = 0.9 * lc.rho(19);
    lc.eta(20) = 1e10 * lc.eta(19);
    lc.sigma(20) = 5e-15;
    // When the corner is sought, Then the round-off point does not move it off the elbow.
    EXPECT_EQ(cornerByKnotRemoval(lc).k, 10);
    EXPECT_EQ(cornerByAdaptivePruning(lc).k, 10);
}
