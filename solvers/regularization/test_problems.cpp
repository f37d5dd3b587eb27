#include "solvers/regularization/test_problems.h"

#include <cmath>
#include <cstdint>

namespace sculptline::solvers::regularization {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Midpoint discretization of ∫ K(s, t) x(t) dt on [s0, s1] × [t0, t1].
template <typename Kernel, typename Solution>
TestProblem discretize(const std::string& name, int n, double s0, double s1, double t0, double t1, Kernel k,
                       Solution x)
{
    TestProblem p;
    p.name = name;
    p.a.resize(n, n);
    p.x.resize(n);
    const double hs = (s1 - s0) / n, ht = (t1 - t0) / n;
    for (int j = 0; j < n; ++j) p.x(j) = x(t0 + (j + 0.5) * ht);
    for (int i = 0; i < n; ++i) {
        const double s = s0 + (i + 0.5) * hs;
        for (int j = 0; j < n; ++j) p.a(i, j) = ht * k(s, t0 + (j + 0.5) * ht);
    }
    p.b = p.a * p.x;
    return p;
}

double phillipsPhi(double x) { return std::abs(x) < 3.0 ? 1.0 + std::cos(kPi * x / 3.0) : 0.0; }

}  // namespace

TestProblem shaw(int n)
{
    return discretize(
        "shaw", n, -kPi / 2, kPi / 2, -kPi / 2, kPi / 2,
        [](double s, double t) {
            const double c = std::cos(s) + std::cos(t);
            const double u = kPi * (std::sin(s) + std::sin(t));
            const double sinc = u == 0.0 ? 1.0 : std::sin(u) / u;
            return c * c * sinc * sinc;
        },
        [](double t) { return 2.0 * std::exp(-6.0 * (t - 0.8) * (t - 0.8)) + std::exp(-2.0 * (t + 0.5) * (t + 0.5)); });
}

TestProblem phillips(int n)
{
    return discretize("phillips", n, -6.0, 6.0, -6.0, 6.0, [](double s, double t) { return phillipsPhi(s - t); },
                      phillipsPhi);
}

TestProblem baart(int n)
{
    return discretize("baart", n, 0.0, kPi / 2, 0.0, kPi, [](double s, double t) { return std::exp(s * std::cos(t)); },
                      [](double t) { return std::sin(t); });
}

TestProblem heat(int n)
{
    // Collocation at the right ends s_i = i h, midpoints t_j = (j − 1/2) h: A(i, j) = h k((i − j + 1/2) h)
    // for i >= j (Regularization Tools' heat: a lower-triangular Toeplitz matrix).
    const double kappa = 1.0, h = 1.0 / n;
    auto kernel = [kappa](double tau) {
        return std::pow(tau, -1.5) * std::exp(-1.0 / (4.0 * kappa * kappa * tau)) / (2.0 * kappa * std::sqrt(kPi));
    };
    TestProblem p;
    p.name = "heat";
    p.a = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j <= i; ++j) p.a(i, j) = h * kernel((i - j + 0.5) * h);
    // The exact solution: on the first half, with τ = 20 t, a parabola, a cap and an exponential tail;
    // zero on the second half.
    p.x.resize(n);
    for (int j = 0; j < n; ++j) {
        const double tau = 20.0 * (j + 1) * h;
        p.x(j) = j + 1 > n / 2 ? 0.0
                 : tau < 2.0   ? 0.75 * tau * tau / 4.0
                 : tau < 3.0   ? 0.75 + (tau - 2.0) * (3.0 - tau)
                               : 0.75 * std::exp(-(tau - 3.0) * 2.0);
    }
    p.b = p.a * p.x;
    return p;
}

TestProblem foxgood(int n)
{
    return discretize("foxgood", n, 0.0, 1.0, 0.0, 1.0, [](double s, double t) { return std::sqrt(s * s + t * t); },
                      [](double t) { return t; });
}

std::vector<TestProblem> hansenProblems(int n) { return {shaw(n), phillips(n), baart(n), heat(n), foxgood(n)}; }

Eigen::VectorXd withNoise(const Eigen::VectorXd& b, double level, unsigned seed)
{
    // SplitMix64 and Box–Muller: std::normal_distribution differs between standard libraries.
    std::uint64_t state = seed;
    auto next = [&state] {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    };
    Eigen::VectorXd e(b.size());
    for (int i = 0; i < e.size(); ++i) {
        const double u1 = 1.0 - next(), u2 = next();
        e(i) = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
    }
    return b + e * (level * b.norm() / e.norm());
}

}  // namespace sculptline::solvers::regularization
