#include "model/constraint.h"

#include <cstddef>

namespace sculptline::model {

namespace {

// dofPerUse: see ConstraintTypeInfo.
const std::array<ConstraintTypeInfo, 10> kConstraintTypes{{
    {ConstraintType::Placement, "placement", true, 0},
    {ConstraintType::Construction, "construction", true, -1},
    {ConstraintType::Position, "position", false, 1},
    {ConstraintType::Tangent, "tangent", false, 1},
    {ConstraintType::FixedPoints, "fixed-points", false, -2},
    {ConstraintType::PointOnCurve, "point-on-curve", false, -2},
    {ConstraintType::CurveOnSurface, "curve-on-surface", false, 0},
    {ConstraintType::Normal, "normal", false, 1},
    {ConstraintType::G1, "g1", false, 0},
    {ConstraintType::Smoothing, "smoothing", false, 0},
}};

}  // namespace

const std::array<ConstraintTypeInfo, 10>& constraintTypes() { return kConstraintTypes; }
const ConstraintTypeInfo& describe(ConstraintType type) { return kConstraintTypes.at(static_cast<size_t>(type)); }
const char* constraintTypeName(ConstraintType type) { return describe(type).name; }
std::optional<ConstraintType> constraintTypeFromName(const std::string& name)
{
    for (const ConstraintTypeInfo& info : kConstraintTypes) {
        if (name == info.name) return info.type;
    }
    return std::nullopt;
}

std::string constraintShapeError(ConstraintType type, const std::vector<EntityKind>& targets, size_t parameters, size_t indices)
{
    const std::string name = constraintTypeName(type);
    auto kinds = [&](std::initializer_list<EntityKind> want, const char* what) -> std::string {
        if (targets.size() != want.size()) return name + ": relates " + what;
        size_t k = 0;
        for (EntityKind kind : want) {
            if (targets[k] != kind) return name + ": target " + std::to_string(k) + " must be a " + kindName(kind) + " (it relates " + what + ")";
            ++k;
        }
        return {};
    };
    std::string error;
    switch (type) {
    case ConstraintType::Placement:
    case ConstraintType::Construction: return name + ": made by the model from the entity it builds, not added";
    case ConstraintType::Position:
    case ConstraintType::Tangent:
        error = kinds({EntityKind::Curve}, "one curve");
        if (error.empty() && parameters != 1) error = name + ": needs one parameter u on the curve";
        return error;
    case ConstraintType::FixedPoints:
        error = kinds({EntityKind::Curve}, "one curve");
        if (error.empty() && indices == 0) error = name + ": names no control point";
        return error;
    case ConstraintType::PointOnCurve:
        error = kinds({EntityKind::Point, EntityKind::Curve}, "a point and a curve");
        if (error.empty() && parameters > 1) error = name + ": at most one parameter u on the curve";
        return error;
    case ConstraintType::CurveOnSurface: return kinds({EntityKind::Curve, EntityKind::Surface}, "a curve and a surface");
    case ConstraintType::Normal:
        error = kinds({EntityKind::Surface}, "one surface");
        if (error.empty() && parameters != 2) error = name + ": needs parameters (u, v) on the surface";
        return error;
    case ConstraintType::G1: return kinds({EntityKind::Surface, EntityKind::Surface}, "two surfaces");
    case ConstraintType::Smoothing: return targets.size() == 1 ? std::string() : name + ": relates one entity";
    }
    return name + ": unknown type";
}

solvers::Curve3d preimageCurve(const solvers::Curve2d& domain)
{
    std::vector<Eigen::Vector3d> uv;
    uv.reserve(domain.points().size());
    for (const Eigen::Vector2d& p : domain.points()) uv.emplace_back(p.x(), p.y(), 0.0);
    return solvers::Curve3d(domain.degree(), domain.knots(), std::move(uv), domain.weights(), domain.isClosed());
}

solvers::Curve2d preimageDomain(const solvers::Curve3d& preimage)
{
    std::vector<Eigen::Vector2d> uv;
    uv.reserve(preimage.points().size());
    for (const Eigen::Vector3d& p : preimage.points()) uv.emplace_back(p.x(), p.y());
    return solvers::Curve2d(preimage.degree(), preimage.knots(), std::move(uv), preimage.weights(), preimage.isClosed());
}

}  // namespace sculptline::model
