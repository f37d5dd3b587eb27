#include "solvers/deformation/deformation_region.h"

namespace sculptline::solvers::deformation {

double grevilleAbscissa(const Surface3d& surface, Direction d, int i)
{
    const int p = surface.degree(d);
    const KnotVector& t = surface.knots(d);
    double sum = 0.0;
    for (int k = 1; k <= p; ++k) sum += t[i + k];
    return sum / p;
}

bool insidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p)
{
    // Crossing number (W. R. Franklin, PNPOLY): a ray towards +u crosses the boundary an odd
    // number of times from inside.
    bool inside = false;
    const size_t n = polygon.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const Eigen::Vector2d& a = polygon[i];
        const Eigen::Vector2d& b = polygon[j];
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
            inside = !inside;
        }
    }
    return inside;
}

std::vector<bool> insideBound(const Surface3d& surface, const std::vector<Eigen::Vector2d>& bound)
{
    const int nu = surface.countU(), nv = surface.countV();
    std::vector<bool> inside(static_cast<size_t>(nu) * nv, true);
    if (bound.empty()) return inside;
    for (int i = 0; i < nu; ++i) {
        const double xi = grevilleAbscissa(surface, Direction::U, i);
        for (int j = 0; j < nv; ++j) {
            const double eta = grevilleAbscissa(surface, Direction::V, j);
            inside[static_cast<size_t>(i) * nv + j] = insidePolygon(bound, Eigen::Vector2d(xi, eta));
        }
    }
    return inside;
}

}  // namespace sculptline::solvers::deformation
