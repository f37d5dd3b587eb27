#include "solvers/geometry/plane_fit.h"

#include "solvers/bspline/geometry_error.h"

#include <Eigen/Eigenvalues>

namespace sculptline::solvers {

PlaneFit bestFitPlane(const std::vector<Eigen::Vector3d>& points)
{
    if (points.empty()) throw GeometryError("points: a plane needs at least one point");
    PlaneFit fit;
    for (const Eigen::Vector3d& p : points) fit.centroid += p;
    fit.centroid /= static_cast<double>(points.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& p : points) scatter += (p - fit.centroid) * (p - fit.centroid).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);  // eigenvalues ascending
    fit.normal = eig.eigenvectors().col(0);
    fit.axisV = eig.eigenvectors().col(1);
    fit.axisU = eig.eigenvectors().col(2);
    fit.spread = eig.eigenvalues();
    return fit;
}

}  // namespace sculptline::solvers
