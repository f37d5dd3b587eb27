#include "solvers/incidence/point_incidence.h"

#include "solvers/bspline/geometry_error.h"

#include <algorithm>

namespace sculptline::solvers::incidence {

Eigen::SparseVector<double> surfacePointRow(const SurfaceStructure& f, double u, double v)
{
    const int p = f.degreeU, q = f.degreeV;
    u = std::clamp(u, f.knotsU[p], f.knotsU[f.countU]);
    v = std::clamp(v, f.knotsV[q], f.knotsV[f.countV]);
    const int su = findSpan(p, f.knotsU, u);
    const int sv = findSpan(q, f.knotsV, v);
    double nu[kMaxDegree + 1], nv[kMaxDegree + 1];
    basisFunctions(su, u, p, f.knotsU, nu);
    basisFunctions(sv, v, q, f.knotsV, nv);
    Eigen::SparseVector<double> row(f.columnCount());
    row.reserve((p + 1) * (q + 1));
    for (int a = 0; a <= p; ++a)
        for (int b = 0; b <= q; ++b) row.insert((su - p + a) * f.countV + (sv - q + b)) = nu[a] * nv[b];
    return row;
}

SparseRows discretizedIncidence(const SurfaceStructure& f, const Curve2d& g, const std::vector<double>& parameters)
{
    if (g.isRational()) throw GeometryError("domain curve: must be non-rational");
    std::vector<Eigen::Triplet<double>> triplets;
    for (size_t k = 0; k < parameters.size(); ++k) {
        const double t = std::clamp(parameters[k], g.domainStart(), g.domainEnd());
        const Eigen::Vector2d uv = g.evaluate(t);
        const Eigen::SparseVector<double> row = surfacePointRow(f, uv.x(), uv.y());
        for (Eigen::SparseVector<double>::InnerIterator it(row); it; ++it)
            triplets.emplace_back(static_cast<int>(k), static_cast<int>(it.index()), it.value());
    }
    SparseRows a(static_cast<Eigen::Index>(parameters.size()), f.columnCount());
    a.setFromTriplets(triplets.begin(), triplets.end());
    return a;
}

std::vector<double> uniformParameters(const Curve2d& g, int m)
{
    if (m < 2) throw GeometryError("parameters: need at least 2, got " + std::to_string(m));
    std::vector<double> t(static_cast<size_t>(m));
    for (int k = 0; k < m; ++k) t[k] = g.domainStart() + (g.domainEnd() - g.domainStart()) * k / (m - 1);
    t.back() = g.domainEnd();
    return t;
}

SparseRows evaluationMatrix(int degree, const KnotVector& knots, const std::vector<double>& parameters)
{
    const int count = static_cast<int>(knots.size()) - degree - 1;
    std::vector<Eigen::Triplet<double>> triplets;
    double n[kMaxDegree + 1];
    for (size_t k = 0; k < parameters.size(); ++k) {
        const double t = std::clamp(parameters[k], knots[degree], knots[count]);
        const int span = findSpan(degree, knots, t);
        basisFunctions(span, t, degree, knots, n);
        for (int a = 0; a <= degree; ++a) triplets.emplace_back(static_cast<int>(k), span - degree + a, n[a]);
    }
    SparseRows e(static_cast<Eigen::Index>(parameters.size()), count);
    e.setFromTriplets(triplets.begin(), triplets.end());
    return e;
}

}  // namespace sculptline::solvers::incidence
