#pragma once
// Hansen's discrete ill-posed test problems (Regularization Tools; P. C. Hansen, "Regularization
// Tools version 4.0 for Matlab 7.3", Numer. Algorithms 46 (2007) 189–194), discretized here from
// their integral equations by the midpoint rule: A x ≈ b with the exact x sampled at the midpoints and
// b = A x (so the only error in b is the noise added by withNoise). Every method is judged by its
// error against x.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace sculptline::solvers::regularization {

struct TestProblem {
    std::string name;
    Eigen::MatrixXd a;  ///< n×n
    Eigen::VectorXd x;  ///< the exact solution
    Eigen::VectorXd b;  ///< A x
};

/// Shaw 1972: 1-D image restoration, K(s, t) = (cos s + cos t)² (sin u / u)², u = π (sin s + sin t),
/// s, t ∈ [−π/2, π/2]; x(t) = 2 exp(−6 (t − 0.8)²) + exp(−2 (t + 0.5)²).
TestProblem shaw(int n);
/// Phillips 1962: K(s, t) = φ(s − t), φ(x) = 1 + cos(π x / 3) for |x| < 3 else 0, on [−6, 6]; x = φ.
TestProblem phillips(int n);
/// Baart 1982: K(s, t) = exp(s cos t), s ∈ [0, π/2], t ∈ [0, π]; x(t) = sin t.
TestProblem baart(int n);
/// Inverse heat equation (Carasso 1982): Volterra kernel K(s, t) = k(s − t), k(τ) = τ^{−3/2}
/// exp(−1/(4κ² τ)) / (2κ √π), κ = 1, on [0, 1], collocated at the right ends of the n intervals;
/// x: a smooth bump on the first half, zero after.
TestProblem heat(int n);
/// Fox & Goodwin: K(s, t) = √(s² + t²) on [0, 1]; x(t) = t.
TestProblem foxgood(int n);

/// The five above, each of size n.
std::vector<TestProblem> hansenProblems(int n);

/// b + e with white Gaussian e scaled to ‖e‖ = level · ‖b‖, from a fixed seed (a portable generator:
/// the same numbers on every platform).
Eigen::VectorXd withNoise(const Eigen::VectorXd& b, double level, unsigned seed);

}  // namespace sculptline::solvers::regularization
