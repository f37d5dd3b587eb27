#include "solvers/deformation/isocurve_deformation.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/deformation/constraint_geometry.h"
#include "solvers/deformation/deformation_region.h"

#include <algorithm>
#include <map>
#include <string>

namespace sculptline::solvers::deformation {
namespace {

using editing::ConstraintType;
using editing::CurveConstraint;
using editing::CurveManipulationSolver;

// Constraint points whose v differ by less than this fraction of the v domain share one iso-curve:
// global projection returns the feet of points on one iso-curve with v equal to ~1e-12 only, and
// separate iso-curves 1e-12 apart would give each column two contradictory pins. A merged point is
// pinned at the group's v with its target shifted by S(u, v_group) − S(u, v): the error left is
// |Δv| times the change of S_v, far below 1e-9 of the model.
constexpr double kSameIsoCurveRelative = 1e-9;

struct Pin {
    double u, v;
    Eigen::Vector3d target;
};

// Non-zero basis functions N_{first..first+p}(t) in `values`; returns first.
int basisAt(int degree, const KnotVector& knots, double t, double* values)
{
    const int span = findSpan(degree, knots, t);
    basisFunctions(span, t, degree, knots, values);
    return span - degree;
}

void merge(ManipulationReport& into, const ManipulationReport& stage)
{
    into.compromise = into.compromise || stage.compromise || stage.tooFewFreePoints;
    into.tooFewFreePoints = into.tooFewFreePoints || stage.tooFewFreePoints;
    if (into.message.empty() && !stage.message.empty()) into.message = "isocurves: " + stage.message;
}

}  // namespace

Surface3d deformByIsocurves(const Surface3d& surface, const std::vector<SurfaceConstraint>& constraints,
                            const DeformationOptions& options, DeformationReport* report)
{
    if (surface.isRational()) throw GeometryError("surface: the isocurves method needs a non-rational surface");
    if (!(options.stiffness > 0.0 && options.stiffness <= 1.0)) {
        throw GeometryError("stiffness: " + std::to_string(options.stiffness) + " is outside (0, 1]");
    }
    const int nu = surface.countU(), nv = surface.countV();
    const int p = surface.degreeU(), q = surface.degreeV();
    const double lambda = options.stiffness;

    // The constraint points with their stiffness-scaled targets (eq. 6-20).
    std::vector<std::vector<Eigen::Vector2d>> keyUv(constraints.size());
    std::vector<std::vector<double>> keyT(constraints.size());
    std::vector<Eigen::Vector3d> keyPoints;
    std::vector<Pin> pins;
    auto pin = [&](const Eigen::Vector2d& uv, const Eigen::Vector3d& target, const std::string& field) {
        detail::requireInDomain(surface, uv, field);
        if (!target.allFinite()) throw GeometryError(field + ": target is not a finite number");
        const Eigen::Vector3d now = surface.evaluate(uv.x(), uv.y());
        pins.push_back({uv.x(), uv.y(), now + lambda * (target - now)});
    };
    for (size_t c = 0; c < constraints.size(); ++c) {
        const SurfaceConstraint& k = constraints[c];
        const std::string field = "constraints[" + std::to_string(c) + "]";
        if (k.type == SurfaceConstraintType::Position) {
            pin(k.uv, k.value, field + ".uv");
        } else if (k.type == SurfaceConstraintType::Curve) {
            if (!k.target) throw GeometryError(field + ".target: a curve constraint needs a target curve");
            KeyPoints kp = curveKeyPoints(surface, k);
            for (size_t i = 0; i < kp.uv.size(); ++i) {
                const Eigen::Vector3d h = k.target->evaluate(kp.t[i]);
                keyPoints.push_back(h);
                pin(kp.uv[i], h, field + ".domain");
            }
            keyUv[c] = std::move(kp.uv);
            keyT[c] = std::move(kp.t);
        } else {
            throw GeometryError(field + ".type: the isocurves method handles position and curve constraints only");
        }
    }

    std::vector<bool> movable = insideBound(surface, options.bound);
    for (size_t b = 0; b < options.blocked.size(); ++b) {
        const auto [i, j] = options.blocked[b];
        if (i < 0 || i >= nu || j < 0 || j >= nv) throw GeometryError("blocked[" + std::to_string(b) + "]: outside the net");
        movable[static_cast<size_t>(i) * nv + j] = false;
    }

    DeformationReport local;
    DeformationReport& rep = report ? *report : local;
    rep = DeformationReport();
    std::vector<Eigen::Vector3d> points = surface.points();

    // Stage 1 (eq. 6-17): the U iso-curve through each distinct v, its control points
    // c_i = Σ_j N_j(v) P_ij moved by the least change that meets the points on it.
    std::map<double, std::vector<Pin>> byV;
    const double sameV =
        kSameIsoCurveRelative * (surface.domainEnd(Direction::V) - surface.domainStart(Direction::V));
    for (const Pin& pn : pins) {
        auto near = byV.lower_bound(pn.v - sameV);
        if (near != byV.end() && near->first <= pn.v + sameV) {
            const Eigen::Vector3d shift = surface.evaluate(pn.u, near->first) - surface.evaluate(pn.u, pn.v);
            near->second.push_back({pn.u, near->first, pn.target + shift});
        } else {
            byV[pn.v].push_back(pn);
        }
    }
    // Per column i: the V-curve positions C_i(v) = c_i + Δc_i it must reach (eq. 6-18).
    std::vector<std::vector<CurveConstraint<3>>> columnPins(static_cast<size_t>(nu));
    double nvv[kMaxDegree + 1], nuu[kMaxDegree + 1];
    for (const auto& [v, group] : byV) {
        const int firstJ = basisAt(q, surface.knotsV(), v, nvv);
        std::vector<Eigen::Vector3d> c(static_cast<size_t>(nu), Eigen::Vector3d::Zero());
        std::vector<int> blocked;
        for (int i = 0; i < nu; ++i) {
            bool any = false;
            for (int b = 0; b <= q; ++b) {
                c[static_cast<size_t>(i)] += nvv[b] * surface.point(i, firstJ + b);
                any = any || (nvv[b] != 0.0 && movable[static_cast<size_t>(i) * nv + firstJ + b]);
            }
            if (!any) blocked.push_back(i);
        }
        const BSplineCurve<3> iso(p, surface.knotsU(), c);
        std::vector<CurveConstraint<3>> onIso;
        std::vector<bool> reached(static_cast<size_t>(nu), false);
        for (const Pin& pn : group) {
            CurveConstraint<3> k;
            k.type = ConstraintType::Position;
            k.u = pn.u;
            k.value = pn.target;
            onIso.push_back(k);
            const int firstI = basisAt(p, surface.knotsU(), pn.u, nuu);
            for (int a = 0; a <= p; ++a) reached[static_cast<size_t>(firstI + a)] = reached[static_cast<size_t>(firstI + a)] || nuu[a] != 0.0;
        }
        ManipulationReport stage;
        const BSplineCurve<3> moved = editing::constrainCurve(iso, onIso, blocked, &stage);
        merge(rep, stage);
        for (int i = 0; i < nu; ++i) {
            if (!reached[static_cast<size_t>(i)]) continue;
            CurveConstraint<3> k;
            k.type = ConstraintType::Position;
            k.u = v;
            k.value = moved.points()[static_cast<size_t>(i)];
            columnPins[static_cast<size_t>(i)].push_back(k);
        }
    }

    // Stage 2 (eq. 6-18): each column's V-curve meets its pins with the least change.
    for (int i = 0; i < nu; ++i) {
        if (columnPins[static_cast<size_t>(i)].empty()) continue;
        std::vector<Eigen::Vector3d> column;
        std::vector<int> blocked;
        for (int j = 0; j < nv; ++j) {
            column.push_back(surface.point(i, j));
            if (!movable[static_cast<size_t>(i) * nv + j]) blocked.push_back(j);
        }
        ManipulationReport stage;
        const BSplineCurve<3> moved =
            editing::constrainCurve(BSplineCurve<3>(q, surface.knotsV(), column), columnPins[static_cast<size_t>(i)], blocked, &stage);
        merge(rep, stage);
        for (int j = 0; j < nv; ++j) points[static_cast<size_t>(i) * nv + j] = moved.points()[static_cast<size_t>(j)];
    }

    Surface3d result(p, q, surface.knotsU(), surface.knotsV(), nu, nv, points);
    rep.constraintRows = 3 * static_cast<int>(pins.size());
    rep.freePoints = static_cast<int>(std::count(movable.begin(), movable.end(), true));
    rep.keyPoints = std::move(keyPoints);
    for (size_t i = 0; i < points.size(); ++i) rep.moved += points[i] != surface.points()[i] ? 1 : 0;
    rep.residuals = constraintResiduals(surface, result, constraints, constraints, keyUv, keyT, lambda);
    rep.maxResidual = rep.residuals.empty() ? 0.0 : *std::max_element(rep.residuals.begin(), rep.residuals.end());
    flagUnmet(surface, constraints, rep);
    return result;
}

}  // namespace sculptline::solvers::deformation
