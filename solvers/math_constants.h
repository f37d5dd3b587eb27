#pragma once
// Mathematical constants of the solvers, one definition each (C++17 has no std::numbers, and M_PI
// is a POSIX extension that strict compilers hide).

namespace sculptline::solvers {

/// pi, rounded to the nearest double.
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace sculptline::solvers
