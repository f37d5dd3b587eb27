#include "tests/volume/test_shapes.h"

#include "solvers/math_constants.h"
#include "solvers/surfaces/revolve.h"

#include <cmath>

namespace sculptline::volume_test {

solvers::Surface3d sphere(double radius, const Eigen::Vector3d& centre)
{
    const double w = std::sqrt(0.5);
    const std::vector<Eigen::Vector3d> points{{0, 0, -radius}, {radius, 0, -radius}, {radius, 0, 0}, {radius, 0, radius}, {0, 0, radius}};
    std::vector<Eigen::Vector3d> moved;
    for (const Eigen::Vector3d& p : points) moved.push_back(p + centre);
    const solvers::Curve3d halfCircle(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, moved, {1, w, 1, w, 1});
    solvers::surfaces::Axis axis;
    axis.point = centre;
    axis.direction = Eigen::Vector3d::UnitZ();
    return solvers::surfaces::revolve(halfCircle, axis, 360.0);
}

solvers::Surface3d bilinear(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p01,
                            const Eigen::Vector3d& p11)
{
    return solvers::Surface3d(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {p00, p01, p10, p11});
}

solvers::Surface3d flatPatch(double a, double b) { return bilinear({0, 0, 0}, {a, 0, 0}, {0, b, 0}, {a, b, 0}); }

std::vector<solvers::Surface3d> cubeFaces(double a)
{
    const auto c = [a](int x, int y, int z) { return Eigen::Vector3d(a * x, a * y, a * z); };
    return {bilinear(c(0, 0, 0), c(1, 0, 0), c(0, 1, 0), c(1, 1, 0)), bilinear(c(0, 0, 1), c(1, 0, 1), c(0, 1, 1), c(1, 1, 1)),
            bilinear(c(0, 0, 0), c(1, 0, 0), c(0, 0, 1), c(1, 0, 1)), bilinear(c(0, 1, 0), c(1, 1, 0), c(0, 1, 1), c(1, 1, 1)),
            bilinear(c(0, 0, 0), c(0, 1, 0), c(0, 0, 1), c(0, 1, 1)), bilinear(c(1, 0, 0), c(1, 1, 0), c(1, 0, 1), c(1, 1, 1))};
}

double twoBallUnionVolume(double r, double d)
{
    const double ball = 4.0 / 3.0 * solvers::kPi * r * r * r;
    const double lens = solvers::kPi * (4.0 * r + d) * (2.0 * r - d) * (2.0 * r - d) / 12.0;
    return 2.0 * ball - lens;
}

}  // namespace sculptline::volume_test
