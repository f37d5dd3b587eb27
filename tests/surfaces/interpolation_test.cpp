// Global interpolation (A9.1) with kept factorization: data met, dense and sparse paths agree,
// reproduction of a cubic, coincident parameters refused.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/interpolation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;

namespace {

constexpr double kExact = 1e-9;

ControlMatrix sampled(const std::vector<double>& t)
{
    ControlMatrix m(static_cast<Eigen::Index>(t.size()), 2);
    for (size_t k = 0; k < t.size(); ++k) m.row(k) << std::sin(7 * t[k]), t[k] * t[k] * t[k] - t[k];
    return m;
}

std::vector<double> graded(int n)
{
    std::vector<double> t;
    for (int k = 0; k < n; ++k) t.push_back(std::pow(static_cast<double>(k) / (n - 1), 1.5));
    return t;
}

}  // namespace

TEST(Interpolation, GivenDenseAndSparseSizes_WhenSolved_ThenDataMet)
{
    for (int n : {12, kDenseInterpolationLimit + 200}) {
        const std::vector<double> t = graded(n);
        const CurveInterpolator interp(t, 3);
        const ControlMatrix data = sampled(t);
        const ControlMatrix ctrl = interp.solve(data);
        const BSplineCurve<2> c = BSplineCurve<2>::fromHomogeneous(3, interp.knots(), ctrl, false);
        for (int k = 0; k < n; ++k) EXPECT_LT((c.evaluate(t[k]) - data.row(k).transpose()).norm(), kExact) << n << " " << k;
        // The second column is a cubic: interpolation reproduces it everywhere, not just at the data.
        for (int s = 0; s <= 50; ++s) {
            const double u = s / 50.0;
            EXPECT_NEAR(c.evaluate(u).y(), u * u * u - u, kExact);
        }
    }
}

TEST(Interpolation, GivenCoincidentParameters_WhenFactored_ThenClearError)
{
    EXPECT_THROW(CurveInterpolator({0.0, 0.5, 0.5, 1.0}, 2), GeometryError);
    EXPECT_THROW(CurveInterpolator({0.0, 1.0}, 2), GeometryError);  // degree too high for two points
}

TEST(Interpolation, GivenKnots_WhenGreville_ThenAveragesAndChordsNormalized)
{
    const std::vector<double> g = grevilleAbscissae(2, {0, 0, 0, 0.5, 1, 1, 1});
    ASSERT_EQ(g.size(), 4u);
    EXPECT_DOUBLE_EQ(g[1], 0.25);
    EXPECT_DOUBLE_EQ(g[2], 0.75);
    ControlMatrix rows(3, 3);
    rows << 0, 0, 0, 3, 0, 0, 3, 4, 0;
    const std::vector<double> t = chordParameters(rows, 3);
    EXPECT_DOUBLE_EQ(t[1], 3.0 / 7.0);
    EXPECT_DOUBLE_EQ(t[2], 1.0);
}
