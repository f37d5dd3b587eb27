#pragma once
// Polynomials in Bernstein form on [0, 1]: products, subdivision and root isolation. The building
// blocks of the exact composition F(G) (seed 000 §2.1; DeRose, Goldman, Hagen, Mann 1993) and of the
// domain curves' knot-line crossings. A polynomial of degree n is its n + 1 coefficients b_k of
// B_k^n(s) = C(n, k) s^k (1 - s)^(n - k).
#include <Eigen/Core>

#include <vector>

namespace sculptline::solvers::incidence {

/// Coefficients of the product of a (degree a.size()-1) and b (degree b.size()-1), degree m + n:
/// c_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) a_i b_j (Farin, "Curves and Surfaces for CAGD", §5.9).
/// Every term is a convex-type weight times a product, so the result carries round-off only.
Eigen::VectorXd bernsteinProduct(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

/// The value at s (de Casteljau, The NURBS Book A1.5).
double bernsteinValue(const Eigen::VectorXd& c, double s);

/// The coefficients of the pieces on [0, s] and [s, 1] (de Casteljau subdivision).
void bernsteinSplit(const Eigen::VectorXd& c, double s, Eigen::VectorXd& left, Eigen::VectorXd& right);

/// The roots in [0, 1] of the polynomial with coefficients c, by recursive subdivision (Bezier
/// root isolation): a piece whose coefficients all lie on one side of zero (beyond
/// `zeroTolerance`) has no root (convex hull property); a piece whose ends have opposite signs and
/// whose coefficients change sign once holds exactly one simple root (Descartes' rule of signs for
/// the Bernstein basis), found by bisection to round-off; a piece whose coefficients are all within
/// `zeroTolerance` of zero (a touch: the polynomial stays that close to zero there) is one root
/// range, and anything else is subdivided down to `width`. Touching ranges merge and are reported
/// by their middle (an end of [0, 1] when they reach it). A polynomial whose coefficients are all
/// within `zeroTolerance` of zero (a curve running along the level) yields no root. Sorted.
/// @param zeroTolerance absolute, in the units of the coefficients (>= 0)
/// @param width         in s, (0, 1): the resolution of non-simple roots
std::vector<double> bernsteinRoots(const Eigen::VectorXd& c, double zeroTolerance, double width = 1e-10);

}  // namespace sculptline::solvers::incidence
