#pragma once
#include <stdexcept>
#include <string>

namespace sculptline::solvers {

/// Thrown when geometry is invalid (wrong knot count, decreasing knots, non-finite numbers,
/// non-positive weights, ...) or an operation's preconditions do not hold. The message names the
/// offending field and the problem, so that the CLI and the GUI can show it verbatim.
class GeometryError : public std::invalid_argument {
public:
    explicit GeometryError(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace sculptline::solvers
