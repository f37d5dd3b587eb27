// The model's entities as geometry: their derived forms (a curve placed by its plane's frame) and the
// checks views and edits make on them (finite coordinates, a curve's extent).
#include "model/model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace sculptline::model {

size_t Entity::tangentSurfaceCount() const
{
    if (!recipe) return 0;
    std::set<std::uint32_t> surfaces;
    for (const SurfaceRecipe::Tangent& t : recipe->tangents) surfaces.insert(t.surface);
    return surfaces.size();
}

solvers::Curve3d transformCurve(const solvers::Curve3d& curve, const PlaneFrame& frame)
{
    std::vector<Eigen::Vector3d> points;
    points.reserve(curve.points().size());
    for (const Eigen::Vector3d& p : curve.points()) points.push_back(frame.toWorld(p));
    return solvers::Curve3d(curve.degree(), curve.knots(), points, curve.weights(), curve.isClosed());
}

solvers::Curve3d flattenToPlane(const solvers::Curve3d& local)
{
    std::vector<Eigen::Vector3d> flat = local.points();
    for (Eigen::Vector3d& p : flat) p.z() = 0.0;
    return solvers::Curve3d(local.degree(), local.knots(), flat, local.weights(), local.isClosed());
}

namespace {

template <typename Points>
bool allFinite(const Points& points)
{
    return std::all_of(points.begin(), points.end(), [](const auto& p) { return p.allFinite(); });
}

template <typename Geometry>
bool finiteSpline(const Geometry& g)
{
    return allFinite(g.points()) && std::all_of(g.weights().begin(), g.weights().end(), [](double w) { return std::isfinite(w); });
}

}  // namespace

double curveExtent(const solvers::Curve3d& curve)
{
    Eigen::Vector3d lo = curve.points().front(), hi = lo;
    for (const Eigen::Vector3d& p : curve.points()) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return (hi - lo).norm();
}

void requireCurveExtent(const solvers::Curve3d& curve, double minimum)
{
    const double extent = curveExtent(curve);
    if (!(extent >= minimum)) {
        char text[160];
        std::snprintf(text, sizeof text, "the curve would span %.3g mm, less than the %.3g mm it must span", extent, minimum);
        throw std::invalid_argument(text);
    }
}

bool hasFiniteGeometry(const Entity& e)
{
    switch (e.kind) {
    case EntityKind::Plane:
        return e.frame.origin.allFinite() && e.frame.rotation.coeffs().allFinite() && std::isfinite(e.frame.size);
    case EntityKind::Curve: return (!e.local || finiteSpline(*e.local)) && (!e.world || finiteSpline(*e.world));
    case EntityKind::Surface: return !e.surface || finiteSpline(*e.surface);
    case EntityKind::Mesh: return !e.mesh || (allFinite(e.mesh->vertices) && allFinite(e.mesh->normals));
    case EntityKind::Point: return e.position.allFinite();
    case EntityKind::Solid: return !e.solid || allFinite(e.solid->mesh.vertices);
    }
    return false;
}

bool hasFiniteGeometry(const Constraint& c)
{
    if (!c.value.allFinite()) return false;
    if (!c.preimage) return true;
    for (const Eigen::Vector3d& p : c.preimage->points()) {
        if (!p.allFinite()) return false;
    }
    return true;
}

}  // namespace sculptline::model
