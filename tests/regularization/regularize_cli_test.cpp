// sculptline-cli regularize, run as the real binary (../shared/interfaces.md). Given / When / Then.
#include "solvers/regularization/lcurve_corner.h"
#include "solvers/regularization/mtsvd.h"
#include "solvers/regularization/test_problems.h"
#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>

using namespace sculptline::cli_test;
namespace reg = sculptline::solvers::regularization;

namespace {

constexpr double kAgreement = 1e-10;  // relative; the CLI prints shortest round-trip numbers
const std::string kPrefix = "sculptline-cli: ";  // main() starts every error line with it

json matrixJson(const Eigen::MatrixXd& m)
{
    json out = json::array();
    for (int i = 0; i < m.rows(); ++i) {
        json row = json::array();
        for (int j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
        out.push_back(row);
    }
    return out;
}

json vectorJson(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

Eigen::MatrixXd matrixOf(const json& j)
{
    Eigen::MatrixXd m(j.size(), j[0].size());
    for (size_t i = 0; i < j.size(); ++i)
        for (size_t c = 0; c < j[i].size(); ++c) m(i, c) = j[i][c].get<double>();
    return m;
}

Eigen::VectorXd vectorOf(const json& j)
{
    Eigen::VectorXd v(j.size());
    for (size_t i = 0; i < j.size(); ++i) v(i) = j[i].get<double>();
    return v;
}

struct Shaw {
    reg::TestProblem p = reg::shaw(32);
    Eigen::VectorXd b = reg::withNoise(p.b, 1e-3, 1);
};

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }

}  // namespace

TEST(RegularizeCli, GivenShaw_WhenRunWithDefaults_ThenTheCornerSolutionAndLCurveOfTheLibrary)
{
    const Shaw s;
    const json out = runOk("regularize", {{"matrix", matrixJson(s.p.a)}, {"rhs", vectorJson(s.b)}});
    const reg::CachedSvd svd(s.p.a);
    const reg::ProjectedRhs rhs = reg::projectRhs(svd, s.b);
    const reg::LCurve lc = reg::tsvdLCurve(svd, rhs);
    const int corner = reg::lcurveCorner(lc, reg::defaultCornerMethod(false)).k;
    EXPECT_EQ(out["k"].get<int>(), corner);
    EXPECT_EQ(out["corner"].get<int>(), corner);
    EXPECT_LT((vectorOf(out["solution"]) - reg::tsvdSolution(svd, rhs, corner)).norm(),
              kAgreement * s.p.x.norm());
    ASSERT_EQ(out["rho"].size(), static_cast<size_t>(svd.rank()));
    EXPECT_EQ(out["eta"].size(), out["rho"].size());
    EXPECT_EQ(out["singular_values"].size(), out["rho"].size());
    EXPECT_LT((vectorOf(out["rho"]) - lc.rho).norm(), kAgreement * lc.rho.norm());
    EXPECT_TRUE(out.contains("elapsed_ms"));
}

TEST(RegularizeCli, GivenThreeRhsColumnsAndAPrior_WhenRunAtAGivenK_ThenEachColumnIsTsvdWithPrior)
{
    const Shaw s;
    Eigen::MatrixXd b(32, 3), x0(32, 3);
    b << s.b, 2 * s.b, -s.b;
    x0.setConstant(0.25);
    const json out = runOk("regularize", {{"matrix", matrixJson(s.p.a)}, {"rhs", matrixJson(b)},
                                          {"prior", matrixJson(x0)}, {"k", 5}});
    EXPECT_EQ(out["k"].get<int>(), 5);
    const reg::CachedSvd svd(s.p.a);
    const Eigen::MatrixXd expected = reg::tsvdSolution(svd, reg::projectRhs(svd, b, x0), 5);
    const Eigen::MatrixXd x = matrixOf(out["solution"]);
    ASSERT_EQ(x.cols(), 3);
    EXPECT_LT((x - expected).norm(), kAgreement * expected.norm());
}

TEST(RegularizeCli, GivenMtsvd_WhenRunWithDefaultAndExplicitSmoothing_ThenBothAreSecondDifferences)
{
    const Shaw s;
    const json base = {{"matrix", matrixJson(s.p.a)}, {"rhs", vectorJson(s.b)}, {"method", "mtsvd"}, {"k", 6}};
    json explicitL = base;
    explicitL["smoothing"] = matrixJson(reg::secondDifferences(32));
    const json a = runOk("regularize", base), b = runOk("regularize", explicitL);
    const Eigen::VectorXd xa = vectorOf(a["solution"]), xb = vectorOf(b["solution"]);
    EXPECT_LT((xa - xb).norm(), kAgreement * xa.norm());
    // η is ‖L x‖ here, and no larger than TSVD's at the same k.
    json tsvd = base;
    tsvd["method"] = "tsvd";
    const Eigen::VectorXd xt = vectorOf(runOk("regularize", tsvd)["solution"]);
    const Eigen::MatrixXd l = reg::secondDifferences(32);
    EXPECT_NEAR(a["eta"][5].get<double>(), (l * xa).norm(), 1e-9 * (l * xa).norm());
    EXPECT_LE((l * xa).norm(), (l * xt).norm());
}

TEST(RegularizeCli, GivenBadInput_WhenRun_ThenExitTwoWithOneLineNamingTheField)
{
    const json ok = {{"matrix", {{1, 2}, {3, 4}, {5, 7}}}, {"rhs", {1, 2, 3}}};
    const std::vector<std::pair<json, std::string>> cases = {
        {{{"matrix", {{1, 2}, {3}}}, {"rhs", {1, 2}}}, "matrix[1]"},
        {{{"matrix", {{1, 2}, {3, "x"}}}, {"rhs", {1, 2}}}, "matrix[1][1]"},
        {{{"matrix", ok["matrix"]}, {"rhs", {1, 2}}}, "rhs"},
        {{{"matrix", ok["matrix"]}, {"rhs", {1, 2, 3}}, {"k", 3}}, "k"},
        {{{"matrix", ok["matrix"]}, {"rhs", {1, 2, 3}}, {"k", 0}}, "k"},
        {{{"matrix", ok["matrix"]}, {"rhs", {1, 2, 3}}, {"prior", {1}}}, "prior"},
        {{{"matrix", ok["matrix"]}, {"rhs", {1, 2, 3}}, {"method", "lsqr"}}, "method"},
        {{{"matrix", ok["matrix"]}, {"rhs", {1, 2, 3}}, {"method", "mtsvd"}}, "smoothing"},
        {{{"matrix", ok["matrix"]}, {"rhs", {1, 2, 3}}, {"method", "mtsvd"}, {"smoothing", {{1, 2, 3}}}}, "smoothing[0]"},
        {{{"matrix", {{0, 0}, {0, 0}}}, {"rhs", {1, 2}}}, "matrix"},
        {{{"rhs", {1, 2}}}, "matrix"},
    };
    for (const auto& [input, name] : cases) {
        const CliResult r = runCli({"regularize"}, input.dump());
        EXPECT_EQ(r.status, 2) << input.dump();
        EXPECT_EQ(r.err.rfind(kPrefix + name + ":", 0), 0u) << input.dump() << " -> " << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    }
    // NaN cannot be written in JSON; a huge exponent is caught as non-finite by the parser or reader.
    const CliResult nan = runCli({"regularize"}, R"({"matrix": [[1e999, 1]], "rhs": [1]})");
    EXPECT_EQ(nan.status, 2);
    // A huge matrix is refused by its size before anything is allocated for it.
    json huge = {{"matrix", json::array()}, {"rhs", json::array()}};
    for (int i = 0; i < 2001; ++i) {
        huge["matrix"].push_back({1.0});
        huge["rhs"].push_back(1.0);
    }
    const CliResult big = runCli({"regularize"}, huge.dump());
    EXPECT_EQ(big.status, 2);
    EXPECT_EQ(firstLine(big.err).rfind(kPrefix + "matrix:", 0), 0u) << big.err;
}
