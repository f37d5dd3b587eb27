#include "solvers/incidence/spanning_sheet.h"

#include "solvers/bspline/geometry_error.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace sculptline::solvers::incidence {
namespace {

/// The second principal extent below which the points count as one line, relative to the first: a
/// line sampled to round-off (1e-16 relative) is far below it, a visibly bent curve far above.
constexpr double kCollinearRatio = 1e-9;

}  // namespace

Surface3d spanningSheet(const std::vector<Eigen::Vector3d>& points, int count, double margin)
{
    if (count < 4) throw GeometryError("count: a bicubic sheet needs at least 4 control points per direction, got " + std::to_string(count));
    if (!(margin >= 0.0 && std::isfinite(margin))) throw GeometryError("margin: must be finite and not negative");
    if (points.size() < 3) throw GeometryError("points: the curves span no surface (fewer than three points)");
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points) {
        if (!p.allFinite()) throw GeometryError("points: not finite");
        centroid += p;
    }
    centroid /= static_cast<double>(points.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& p : points) scatter += (p - centroid) * (p - centroid).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);  // ascending eigenvalues
    const Eigen::Vector3d spread = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    if (!(spread(2) > 0.0) || spread(1) <= kCollinearRatio * spread(2))
        throw GeometryError("points: the curves lie on one line and span no surface");
    const Eigen::Vector3d e1 = eigen.eigenvectors().col(2).normalized();
    const Eigen::Vector3d e2 = eigen.eigenvectors().col(0).cross(e1).normalized();  // right-handed with the normal
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Eigen::Vector3d& p : points) {
        const Eigen::Vector2d q((p - centroid).dot(e1), (p - centroid).dot(e2));
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    const double grow = margin * (hi - lo).maxCoeff();
    lo -= Eigen::Vector2d::Constant(grow);
    hi += Eigen::Vector2d::Constant(grow);
    constexpr int degree = 3;
    KnotVector knots(static_cast<size_t>(count + degree + 1));
    const int spans = count - degree;
    for (int i = 0; i < static_cast<int>(knots.size()); ++i) {
        knots[static_cast<size_t>(i)] = std::clamp(static_cast<double>(i - degree) / spans, 0.0, 1.0);
    }
    std::vector<double> greville(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        double sum = 0.0;
        for (int k = 1; k <= degree; ++k) sum += knots[static_cast<size_t>(i + k)];
        greville[static_cast<size_t>(i)] = sum / degree;
    }
    std::vector<Eigen::Vector3d> net;
    net.reserve(static_cast<size_t>(count * count));
    for (int i = 0; i < count; ++i) {
        for (int j = 0; j < count; ++j) {
            const double x = lo.x() + greville[static_cast<size_t>(i)] * (hi.x() - lo.x());
            const double y = lo.y() + greville[static_cast<size_t>(j)] * (hi.y() - lo.y());
            net.push_back(centroid + x * e1 + y * e2);
        }
    }
    return Surface3d(degree, degree, knots, knots, count, count, net);
}

}  // namespace sculptline::solvers::incidence
