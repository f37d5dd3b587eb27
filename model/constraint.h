#pragma once
// Constraints: first-class records of the constraint graph (seed 000 §3.2), separate from the
// entities they relate. An entity holds only its own persistent data; what ties it to others — the
// plane a curve is drawn on, the curves a surface is built from, a pin on a curve, a curve lying on
// a surface — is a constraint with a type, the entities (and parameters) it relates, a target value
// and a weight. The planner (model/plan.h) reads entities and constraints to order the solves.
//
// Two kinds of relation:
// - one-way (placement, construction): `sources` determine `targets` completely; a recipe is
//   evaluated in topological order and never feeds back;
// - coupled (position, tangent, fixed points, point on curve, curve on surface, normal, G1,
//   smoothing): the constraint consumes freedom of its `targets` (seed 000 Fig. 3) and is solved
//   together with every other constraint on them; targets coupled through constraints form one
//   cluster (a strongly connected component) that one solver handles.
#include "model/entity_kind.h"
#include "solvers/bspline/bspline_curve.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sculptline::model {

using ConstraintId = std::uint32_t;  ///< 0 is "none"; numbered apart from entities

enum class ConstraintType {
    Placement,       ///< a curve drawn on a plane: its world form is the plane's frame applied
    Construction,    ///< a surface (or mesh) built from curves by a recipe
    Position,        ///< C(u) kept at `value` while the curve changes (a pin)
    Tangent,         ///< C'(u) kept at `value`
    FixedPoints,     ///< control points `indices` of a curve kept where they are
    PointOnCurve,    ///< a point entity lies on a curve (at `parameters[0]` when given)
    CurveOnSurface,  ///< a curve lies on a surface, with its pre-image in the surface's domain
    Normal,          ///< the surface normal at (u, v) = `parameters` is parallel to `value`
    G1,              ///< two surfaces tangent-continuous along a common boundary
    Smoothing,       ///< a fairness term on a surface or curve (`weight` scales it)
};

/// One row of the constraint-type table.
struct ConstraintTypeInfo {
    ConstraintType type;
    const char* name;  ///< as documents and `sculptline-cli plan` spell it
    bool oneWay;       ///< sources determine targets (a recipe) rather than coupling them
    /// Degrees of freedom one use consumes from a target, per model dimension (3 in space, 2 for
    /// a curve in its plane); -1: all of the target's (a recipe), 0: none (a smoothing term), -2:
    /// depends on the record (fixed points: per index, point on curve: one less without a parameter).
    int dofPerUse;
};

const std::array<ConstraintTypeInfo, 10>& constraintTypes();
const ConstraintTypeInfo& describe(ConstraintType type);
const char* constraintTypeName(ConstraintType type);
std::optional<ConstraintType> constraintTypeFromName(const std::string& name);

struct Constraint {
    ConstraintId id = 0;
    ConstraintType type = ConstraintType::Position;
    /// Entities it reads and never changes (a recipe's inputs, the plane of a placement).
    std::vector<EntityId> sources;
    /// Entities whose freedom it consumes (what it makes, or what it couples).
    std::vector<EntityId> targets;
    /// Where on the targets: u on a curve (position, tangent, point on curve), (u, v) on a surface
    /// (normal).
    std::vector<double> parameters;
    /// Control point indices (fixed points), boundary indices (G1).
    std::vector<int> indices;
    /// The target value (a pin's point, a tangent, a normal), world coordinates; recomputed from
    /// the geometry for pins, which hold the curve's present value.
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    double weight = 1.0;
    /// CurveOnSurface: the curve's pre-image in the surface's (u, v) domain (z = 0).
    std::optional<solvers::Curve3d> preimage;
};

/// Why `type` cannot relate targets of these kinds with this many parameters and indices, or empty
/// when it can (the model and the document reader ask the same question): position and tangent
/// take one curve and u; fixed points one curve and indices; point-on-curve a point and a curve
/// (u optional); curve-on-surface a curve and a surface; normal a surface and (u, v); g1 two
/// surfaces; smoothing one entity; placement and construction are the model's own.
std::string constraintShapeError(ConstraintType type, const std::vector<EntityKind>& targets, size_t parameters,
                                 size_t indices);

/// A curve-on-surface pre-image as it is stored (`Constraint::preimage`: points [u, v, 0]) from the
/// domain curve the incidence solver reads, and back; degree, knots and closure are kept, so
/// preimageDomain(preimageCurve(d)) == d exactly.
solvers::Curve3d preimageCurve(const solvers::Curve2d& domain);
solvers::Curve2d preimageDomain(const solvers::Curve3d& preimage);

/// Placement and construction records are derived from the entity they make (its plane, its recipe
/// and inputs), kept by the model as the entity changes; the others are the designer's, added and
/// removed as such (and saved).
inline bool derivedConstraint(ConstraintType type)
{
    return type == ConstraintType::Placement || type == ConstraintType::Construction;
}

}  // namespace sculptline::model
