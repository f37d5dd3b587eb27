// Bernstein polynomials: products and root isolation (the building blocks of the exact composition).
#include "solvers/incidence/bernstein.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers::incidence;

TEST(IncidenceBernstein, ProductIsThePolynomialProduct)
{
    // Given two Bernstein polynomials of degrees 3 and 4
    const Eigen::VectorXd a = (Eigen::VectorXd(4) << 1.0, -2.0, 0.5, 3.0).finished();
    const Eigen::VectorXd b = (Eigen::VectorXd(5) << 0.3, 1.0, -1.0, 2.0, 0.7).finished();
    // When multiplied
    const Eigen::VectorXd c = bernsteinProduct(a, b);
    // Then the product has degree 7 and its values are the products of the values
    ASSERT_EQ(c.size(), 8);
    for (double s : {0.0, 0.13, 0.5, 0.77, 1.0})
        EXPECT_NEAR(bernsteinValue(c, s), bernsteinValue(a, s) * bernsteinValue(b, s), 1e-14);
}

TEST(IncidenceBernstein, RootsOfSimpleTangentialAndEndRoots)
{
    // (s - 0.3)(s - 0.7) in Bernstein form of degree 2: b0 = 0.21, b1 = 0.21 - 0.5 = -0.29, b2 = 0.21
    const Eigen::VectorXd two = (Eigen::VectorXd(3) << 0.21, -0.29, 0.21).finished();
    const std::vector<double> roots = bernsteinRoots(two, 1e-15);
    ASSERT_EQ(roots.size(), 2u);
    EXPECT_NEAR(roots[0], 0.3, 1e-15);
    EXPECT_NEAR(roots[1], 0.7, 1e-15);
    // (s - 0.5)^2 touches zero: found to the subdivision's resolution
    const Eigen::VectorXd touch = (Eigen::VectorXd(3) << 0.25, -0.25, 0.25).finished();
    const std::vector<double> t = bernsteinRoots(touch, 1e-15);
    ASSERT_FALSE(t.empty());
    for (double s : t) EXPECT_NEAR(s, 0.5, 1e-7);
    // s (1 - s): zeros at both ends, none inside
    const Eigen::VectorXd ends = (Eigen::VectorXd(3) << 0.0, 0.5, 0.0).finished();
    EXPECT_EQ(bernsteinRoots(ends, 1e-15), (std::vector<double>{0.0, 1.0}));
    // identically zero: a curve along the line, no crossing
    EXPECT_TRUE(bernsteinRoots(Eigen::VectorXd::Zero(4), 1e-15).empty());
}
