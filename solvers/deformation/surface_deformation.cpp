#include "solvers/deformation/surface_deformation.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "solvers/deformation/constraint_geometry.h"
#include "solvers/deformation/deformation_region.h"
#include "solvers/math_constants.h"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>

namespace sculptline::solvers::deformation {
namespace {

using namespace detail;

// A pivot of the QR of (F R⁻¹)ᵀ below this fraction of the largest marks a dependent row (as in
// curve_manipulation.cpp: far above round-off of basis values, far below any intended constraint).
constexpr double kRankRelativeTolerance = 1e-10;

// Force objective: each node is also tied to its rest position by a weak spring of this stiffness
// relative to the unit bars. Without it a net with no blocked point has rigid translations of zero
// force change, and one dragged point would translate the whole surface; with it the change decays
// over about kAnchorSpring^(-1/4) ≈ 5.6 bars around a constraint (the biharmonic length scale of
// KᵀK + μI), a smooth local fall-off, and H is positive definite (condition ≤ 16²/μ ≈ 2.6e5).
constexpr double kAnchorSpring = 1e-3;

// Least displacement with a bound: the weights grow towards the bound over this many rings of
// control points (a bicubic's support is 4 points wide: 3 rings reach from the bound to where a
// constraint's support typically starts).
constexpr int kFadeRings = 3;

// Distance constraints are non-linear: chord-Newton steps (the factored row direction kept) stop
// when the length error is below this fraction of the length, or after kMaxDistanceSteps.
constexpr double kDistanceRelativeTolerance = 1e-12;
constexpr int kMaxDistanceSteps = 20;

// Graph distance (4-neighbour rings) of every control point from the nearest point outside the
// bound (those are 0; a net with none outside gets a large number everywhere).
std::vector<int> ringsFromOutside(const std::vector<bool>& inside, int nu, int nv)
{
    const int n = nu * nv;
    std::vector<int> ring(static_cast<size_t>(n), n);
    std::vector<int> queue;
    for (int k = 0; k < n; ++k) {
        if (!inside[static_cast<size_t>(k)]) {
            ring[static_cast<size_t>(k)] = 0;
            queue.push_back(k);
        }
    }
    for (size_t head = 0; head < queue.size(); ++head) {
        const int k = queue[head], i = k / nv, j = k % nv;
        const int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
        for (const auto& ij : nb) {
            if (ij[0] < 0 || ij[0] >= nu || ij[1] < 0 || ij[1] >= nv) continue;
            const int o = ij[0] * nv + ij[1];
            if (ring[static_cast<size_t>(o)] > ring[static_cast<size_t>(k)] + 1) {
                ring[static_cast<size_t>(o)] = ring[static_cast<size_t>(k)] + 1;
                queue.push_back(o);
            }
        }
    }
    return ring;
}

using LltPointer = const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>*;

// The operator C with d = C b solving min dᵀHd s.t. F d = b (least squares when F lacks full row
// rank), from Fᵀ (blocks·m × rows; H is block-diagonal with `blocks` copies of the m × m matrix
// factored by `llt`, or I when llt is null). Returns the rank.
//
// With H = RᵀR and e = R d this is the minimum-norm problem min ‖e‖ s.t. G e = b, G = F R⁻¹, solved
// as in CurveManipulationSolver: column-pivoted QR of Gᵀ = Q[R₁ R₂; 0 0]Πᵀ, e = Q₁ y with
// Π[R₁ᵀ; R₂ᵀ] y = b in least squares (eq. 6-9's d = Fᵀ(FFᵀ)⁻¹b for H = I, never forming FFᵀ).
int minimumNormOperator(Eigen::MatrixXd G, int blocks, int m, LltPointer llt, Eigen::MatrixXd& C)
{
    const Eigen::Index cols = G.rows(), rows = G.cols();
    C = Eigen::MatrixXd::Zero(cols, rows);
    if (llt) {
        // H = P⁻¹ L Lᵀ P (Eigen's convention), so R = Lᵀ P and Gᵀ = R⁻ᵀ Fᵀ = L⁻¹ P Fᵀ.
        for (int k = 0; k < blocks; ++k) {
            Eigen::MatrixXd block = llt->permutationP() * G.middleRows(k * m, m);
            llt->matrixL().solveInPlace(block);
            G.middleRows(k * m, m) = block;
        }
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(G);
    qr.setThreshold(kRankRelativeTolerance);
    const int rank = static_cast<int>(qr.rank());
    if (rank == 0) return 0;
    const Eigen::MatrixXd q1 = qr.householderQ() * Eigen::MatrixXd::Identity(cols, rank);
    const Eigen::MatrixXd a = qr.matrixR().topRows(rank).triangularView<Eigen::Upper>().toDenseMatrix().transpose();
    const Eigen::MatrixXd aPlus = a.householderQr().solve(Eigen::MatrixXd::Identity(rows, rows));
    C = q1 * (aPlus * qr.colsPermutation().transpose());
    if (llt) {
        // d = R⁻¹ e = P⁻¹ L⁻ᵀ e, once for all targets.
        for (int k = 0; k < blocks; ++k) {
            Eigen::MatrixXd block = C.middleRows(k * m, m);
            llt->matrixU().solveInPlace(block);
            C.middleRows(k * m, m) = llt->permutationPinv() * block;
        }
    }
    return rank;
}

}  // namespace

const char* boundCaseName(BoundCase c)
{
    switch (c) {
        case BoundCase::Over: return "over";
        case BoundCase::Under: return "under";
        case BoundCase::Well: return "well";
        case BoundCase::Unbounded: break;
    }
    return "unbounded";
}

// One scalar equation Σ_i c_i (dir · P_i) = target on the control points.
struct SurfaceDeformationSolver::Row {
    Coefficients coefficients;
    Eigen::Vector3d direction;
};

void SurfaceDeformationSolver::factor(const Surface3d& surface, const std::vector<SurfaceConstraint>& constraints,
                                      const DeformationOptions& options)
{
    surface_ = surface;
    factored_ = constraints;
    options_ = options;
    if (!(options.stiffness > 0.0 && options.stiffness <= 1.0)) {
        throw GeometryError("stiffness: " + std::to_string(options.stiffness) + " is outside (0, 1]");
    }
    const int nu = surface.countU(), nv = surface.countV();
    const int n = nu * nv;

    // Free points: not blocked, and inside the bound (eq. 6-22).
    std::vector<bool> movable = insideBound(surface, options.bound);
    for (size_t b = 0; b < options.blocked.size(); ++b) {
        const auto [i, j] = options.blocked[b];
        if (i < 0 || i >= nu || j < 0 || j >= nv) {
            throw GeometryError("blocked[" + std::to_string(b) + "]: (" + std::to_string(i) + ", " + std::to_string(j) +
                                ") outside the " + std::to_string(nu) + " x " + std::to_string(nv) + " net");
        }
        movable[static_cast<size_t>(i) * nv + j] = false;
    }
    free_.clear();
    std::vector<int> column(static_cast<size_t>(n), -1);
    for (int k = 0; k < n; ++k) {
        if (movable[static_cast<size_t>(k)]) {
            column[static_cast<size_t>(k)] = static_cast<int>(free_.size());
            free_.push_back(k);
        }
    }
    const int m = static_cast<int>(free_.size());

    // Rows of Table 6-1's constraints.
    std::vector<Row> rows;
    rowOwner_.clear();
    keyUv_.assign(constraints.size(), {});
    keyT_.assign(constraints.size(), {});
    distanceDirection_.assign(constraints.size(), Eigen::Vector3d::Zero());
    boundCases_.assign(constraints.size(), BoundCase::Unbounded);
    nonLinear_ = false;
    std::optional<SurfaceProjector> projector;
    auto add = [&](size_t c, Coefficients coefficients, const Eigen::Vector3d& direction) {
        rows.push_back({std::move(coefficients), direction});
        rowOwner_.push_back(static_cast<int>(c));
    };
    for (size_t c = 0; c < constraints.size(); ++c) {
        const SurfaceConstraint& k = constraints[c];
        switch (k.type) {
            case SurfaceConstraintType::Position: {
                requireInDomain(surface, k.uv, at(c) + ".uv");
                const Coefficients s = basisCoefficients(surface, k.uv.x(), k.uv.y(), 0, 0);
                for (int axis = 0; axis < 3; ++axis) add(c, s, Eigen::Vector3d::Unit(axis));
                break;
            }
            case SurfaceConstraintType::Normal: {
                requireInDomain(surface, k.uv, at(c) + ".uv");
                if (!k.value.allFinite() || k.value.norm() == 0.0) {
                    throw GeometryError(at(c) + ".value: the normal must be a finite non-zero vector");
                }
                const Eigen::Vector3d nrm = k.value.normalized();
                add(c, basisCoefficients(surface, k.uv.x(), k.uv.y(), 1, 0), nrm);  // S_u · n = 0
                add(c, basisCoefficients(surface, k.uv.x(), k.uv.y(), 0, 1), nrm);  // S_v · n = 0
                break;
            }
            case SurfaceConstraintType::Curve: {
                if (!k.target) throw GeometryError(at(c) + ".target: a curve constraint needs a target curve");
                if (!k.domain && !projector) projector.emplace(surface);
                KeyPoints kp = curveKeyPoints(surface, k, projector ? &*projector : nullptr);
                if (!options.bound.empty()) {
                    // §6.3: only the key points well inside the bound act — those whose every
                    // supporting control point is free, so that each can be met and the rest of
                    // the target (the relaxation interval out to the bound) fades to the parent
                    // surface. Under-constrained: the target's inside span; over-constrained:
                    // none, and the surface is not affected.
                    auto supported = [&](const Eigen::Vector2d& uv) {
                        if (!insidePolygon(options.bound, uv)) return false;
                        for (const auto& [i, coef] : basisCoefficients(surface, uv.x(), uv.y(), 0, 0)) {
                            if (coef != 0.0 && !movable[static_cast<size_t>(i)]) return false;
                        }
                        return true;
                    };
                    KeyPoints inside;
                    for (size_t p = 0; p < kp.uv.size(); ++p) {
                        if (!supported(kp.uv[p])) continue;
                        inside.uv.push_back(kp.uv[p]);
                        inside.t.push_back(kp.t[p]);
                    }
                    boundCases_[c] = inside.uv.empty()                  ? BoundCase::Over
                                     : inside.uv.size() < kp.uv.size() ? BoundCase::Under
                                                                       : BoundCase::Well;
                    kp = std::move(inside);
                }
                keyUv_[c] = std::move(kp.uv);
                keyT_[c] = std::move(kp.t);
                const std::vector<Eigen::Vector2d>& uvs = keyUv_[c];
                for (const Eigen::Vector2d& uv : uvs) {
                    requireInDomain(surface, uv, at(c) + ".domain");
                    const Coefficients s = basisCoefficients(surface, uv.x(), uv.y(), 0, 0);
                    for (int axis = 0; axis < 3; ++axis) add(c, s, Eigen::Vector3d::Unit(axis));
                }
                break;
            }
            case SurfaceConstraintType::CurveTangent: {
                if (!k.domain) throw GeometryError(at(c) + ".domain: a curve-tangent constraint needs a domain curve");
                if (!k.value.allFinite() || k.value.norm() == 0.0) {
                    throw GeometryError(at(c) + ".value: the tangent must be a finite non-zero vector");
                }
                const BSplineCurve<2>& G = *k.domain;
                const Eigen::Vector2d a = G.evaluate(G.domainStart()), b = G.evaluate(G.domainEnd());
                const int count =
                    std::min(kMaxKeyPoints, k.keyPoints > 0 ? k.keyPoints : std::max(2, spansCrossed(surface, a, b)));
                const auto [e1, e2] = complement(k.value.normalized());
                for (double t : uniformParameters(G.domainStart(), G.domainEnd(), count)) {
                    const auto g = G.derivatives(t, 1);
                    requireInDomain(surface, g[0], at(c) + ".domain");
                    if (g[1].norm() == 0.0) throw GeometryError(at(c) + ".domain: the curve has no direction");
                    // Across G in the domain: G' turned a quarter; the cross tangent is S_u a + S_v b.
                    const Eigen::Vector2d across = Eigen::Vector2d(-g[1].y(), g[1].x()).normalized();
                    const Coefficients cross =
                        combine(basisCoefficients(surface, g[0].x(), g[0].y(), 1, 0), across.x(),
                                basisCoefficients(surface, g[0].x(), g[0].y(), 0, 1), across.y());
                    keyUv_[c].push_back(g[0]);
                    keyT_[c].push_back(t);
                    add(c, cross, e1);  // cross · e1 = 0 and cross · e2 = 0: cross ∥ value
                    add(c, cross, e2);
                }
                break;
            }
            case SurfaceConstraintType::Angle: {
                // The normal n* nearest to the present one that makes the angle with value: in
                // the plane of value and the present normal (of value and S_u when they are
                // parallel), then Normal's linear rows S_u·n* = S_v·n* = 0 — met exactly, no
                // iteration (the cosine's own linearization is singular where n ∥ value).
                requireInDomain(surface, k.uv, at(c) + ".uv");
                if (!k.value.allFinite() || k.value.norm() == 0.0) throw GeometryError(at(c) + ".value: the direction must be a finite non-zero vector");
                if (!std::isfinite(k.angle) || k.angle < 0.0 || k.angle > kPi) throw GeometryError(at(c) + ".angle: must be in [0, 180] degrees");
                const auto der = surface.derivatives(k.uv.x(), k.uv.y(), 1);
                const Eigen::Vector3d N = der[1][0].cross(der[0][1]);
                if (N.norm() == 0.0) throw GeometryError(at(c) + ".uv: the surface has no normal there");
                const Eigen::Vector3d a = k.value.normalized();
                Eigen::Vector3d tilt = N.normalized() - a * a.dot(N.normalized());
                if (tilt.norm() < 1e-9) tilt = der[1][0] - a * a.dot(der[1][0]);
                if (tilt.norm() == 0.0) throw GeometryError(at(c) + ".uv: the surface has no tangent there to tilt along");
                const Eigen::Vector3d goal = std::cos(k.angle) * a + std::sin(k.angle) * tilt.normalized();
                factored_[c].value2 = goal;  // the residual measures against it
                add(c, basisCoefficients(surface, k.uv.x(), k.uv.y(), 1, 0), goal);
                add(c, basisCoefficients(surface, k.uv.x(), k.uv.y(), 0, 1), goal);
                break;
            }
            case SurfaceConstraintType::Tangents: {
                requireInDomain(surface, k.uv, at(c) + ".uv");
                if (!k.value.allFinite() || !k.value2.allFinite()) throw GeometryError(at(c) + ".value: not a finite number");
                const Coefficients su = basisCoefficients(surface, k.uv.x(), k.uv.y(), 1, 0);
                const Coefficients sv = basisCoefficients(surface, k.uv.x(), k.uv.y(), 0, 1);
                for (int axis = 0; axis < 3; ++axis) add(c, su, Eigen::Vector3d::Unit(axis));
                for (int axis = 0; axis < 3; ++axis) add(c, sv, Eigen::Vector3d::Unit(axis));
                break;
            }
            case SurfaceConstraintType::Distance: {
                requireInDomain(surface, k.uv, at(c) + ".uv");
                requireInDomain(surface, k.uv2, at(c) + ".uv2");
                if (!std::isfinite(k.distance) || k.distance < 0.0) {
                    throw GeometryError(at(c) + ".value: the distance must be a finite number >= 0");
                }
                const Eigen::Vector3d e = surface.evaluate(k.uv2.x(), k.uv2.y()) - surface.evaluate(k.uv.x(), k.uv.y());
                if (e.norm() == 0.0) throw GeometryError(at(c) + ".uv2: the two points coincide; no direction to measure along");
                distanceDirection_[c] = e.normalized();
                nonLinear_ = true;
                // Linearization of |S(uv2) − S(uv)| about the current net: e/|e| · (ΔS2 − ΔS1).
                add(c,
                    combine(basisCoefficients(surface, k.uv2.x(), k.uv2.y(), 0, 0), 1.0,
                            basisCoefficients(surface, k.uv.x(), k.uv.y(), 0, 0), -1.0),
                    distanceDirection_[c]);
                break;
            }
        }
    }

    // F over the free points' changes, ordered [x; y; z], and the rows' current values.
    const int r = static_cast<int>(rows.size());
    F_ = Eigen::MatrixXd::Zero(r, 3 * m);
    current_ = Eigen::VectorXd::Zero(r);
    for (int k = 0; k < r; ++k) {
        for (const auto& [i, coef] : rows[static_cast<size_t>(k)].coefficients) {
            const Eigen::Vector3d& dir = rows[static_cast<size_t>(k)].direction;
            current_[k] += coef * dir.dot(surface.points()[static_cast<size_t>(i)]);
            const int col = column[static_cast<size_t>(i)];
            if (col < 0) continue;
            for (int axis = 0; axis < 3; ++axis) F_(k, axis * m + col) += coef * dir[axis];
        }
    }
    C_ = Eigen::MatrixXd::Zero(3 * m, r);
    C1_ = Eigen::MatrixXd::Zero(m, r / 3);
    F1_ = Eigen::MatrixXd::Zero(0, m);
    rank_ = 0;
    separable_ = false;
    if (r == 0 || m == 0) return;

    // Objective ½ dᵀ H d per coordinate. Displacement: H = I. Force: H = KᵀK + μI, K the bar
    // network's force change Δf_i = Σ_{j~i} q (d_i − d_j) with q = 1 at every node, the nodes
    // outside the free set included: their rows hold the change and its slope at zero across a
    // bound or next to blocked points (the C1 fade of §6.2.4).
    std::optional<Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>> llt;
    if (options.objective == Objective::Force) {
        std::vector<Eigen::Triplet<double>> kt;
        for (int i = 0; i < nu; ++i) {
            for (int j = 0; j < nv; ++j) {
                const int row = i * nv + j;
                const int me = column[static_cast<size_t>(row)];
                const int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
                for (const auto& ij : nb) {
                    if (ij[0] < 0 || ij[0] >= nu || ij[1] < 0 || ij[1] >= nv) continue;
                    const int other = column[static_cast<size_t>(ij[0] * nv + ij[1])];
                    if (me >= 0) kt.emplace_back(row, me, 1.0);
                    if (other >= 0) kt.emplace_back(row, other, -1.0);
                }
            }
        }
        Eigen::SparseMatrix<double> K(n, m);
        K.setFromTriplets(kt.begin(), kt.end());
        Eigen::SparseMatrix<double> H = Eigen::SparseMatrix<double>(K.transpose()) * K;
        for (int i = 0; i < m; ++i) H.coeffRef(i, i) += kAnchorSpring;
        llt.emplace(H);
        if (llt->info() != Eigen::Success) throw GeometryError("surface: the force objective is not positive definite");
    } else if (!options.bound.empty()) {
        // Least displacement inside a bound, relaxed (§6.2.4): min Σ w_i |d_i|² with w_i = (R / r_i)²
        // for the points r_i < R rings in from the bound, so that d_i ∝ 1/w_i fades like r² —
        // value and slope to zero at the bound — and the plain least displacement further in.
        const std::vector<int> rings = ringsFromOutside(insideBound(surface, options.bound), nu, nv);
        Eigen::SparseMatrix<double> H(m, m);
        std::vector<Eigen::Triplet<double>> ht;
        for (int i = 0; i < m; ++i) {
            const int r = rings[static_cast<size_t>(free_[static_cast<size_t>(i)])];
            const double w = r < kFadeRings ? std::pow(static_cast<double>(kFadeRings) / r, 2) : 1.0;
            ht.emplace_back(i, i, w);
        }
        H.setFromTriplets(ht.begin(), ht.end());
        llt.emplace(H);
    }

    // Position, Curve and Tangents rows come in (x, y, z) triples with equal coefficients, and H is
    // the same for each coordinate: then the problem is three copies of one with a third of the rows
    // and columns (27× less QR work), which is what a dragged point or target curve needs.
    separable_ = std::all_of(constraints.begin(), constraints.end(), [](const SurfaceConstraint& k) {
        return k.type == SurfaceConstraintType::Position || k.type == SurfaceConstraintType::Curve ||
               k.type == SurfaceConstraintType::Tangents;
    });
    const LltPointer factorization = llt ? &*llt : nullptr;
    if (separable_) {
        F1_.resize(r / 3, m);
        for (int k = 0; k < r / 3; ++k) F1_.row(k) = F_.block(3 * k, 0, 1, m);
        rank_ = 3 * minimumNormOperator(F1_.transpose(), 1, m, factorization, C1_);
    } else {
        rank_ = minimumNormOperator(F_.transpose(), 3, m, factorization, C_);
    }
}

Eigen::VectorXd SurfaceDeformationSolver::rightHandSide(const std::vector<SurfaceConstraint>& constraints,
                                                        std::vector<Eigen::Vector3d>* keyPoints) const
{
    // b = λ (target − current) row by row (eq. 6-20: D_t = p(u_t) − k_t, f_t = λ D_t).
    const double lambda = options_.stiffness;
    Eigen::VectorXd b(F_.rows());
    std::vector<int> seen(constraints.size(), 0);
    for (Eigen::Index k = 0; k < F_.rows(); ++k) {
        const size_t c = static_cast<size_t>(rowOwner_[static_cast<size_t>(k)]);
        const SurfaceConstraint& s = constraints[c];
        const int local = seen[c]++;
        double target = 0.0;  // Normal and CurveTangent rows: zero
        switch (s.type) {
            case SurfaceConstraintType::Position:
                if (!s.value.allFinite()) throw GeometryError(at(c) + ".value: not a finite number");
                target = s.value[local];
                break;
            case SurfaceConstraintType::Curve: {
                if (!s.target) throw GeometryError(at(c) + ".target: missing");
                const Eigen::Vector3d h = s.target->evaluate(keyT_[c][static_cast<size_t>(local / 3)]);
                if (local % 3 == 0 && keyPoints) keyPoints->push_back(h);
                target = h[local % 3];
                break;
            }
            case SurfaceConstraintType::Tangents:
                if (!s.value.allFinite() || !s.value2.allFinite()) throw GeometryError(at(c) + ".value: not a finite number");
                target = local < 3 ? s.value[local] : s.value2[local - 3];
                break;
            case SurfaceConstraintType::Distance: {
                // The row measures e0·(S2 − S1), currently |e0|: first step towards the length.
                if (!std::isfinite(s.distance) || s.distance < 0.0) throw GeometryError(at(c) + ".value: not a finite number >= 0");
                target = s.distance;
                break;
            }
            default:
                break;
        }
        b[k] = lambda * (target - current_[k]);
    }
    return b;
}

Surface3d SurfaceDeformationSolver::solve(const std::vector<SurfaceConstraint>& constraints,
                                          DeformationReport* report) const
{
    if (constraints.size() != factored_.size()) {
        throw GeometryError("constraints: expected " + std::to_string(factored_.size()) + ", got " +
                            std::to_string(constraints.size()));
    }
    std::vector<Eigen::Vector3d> keyPoints;
    const Eigen::VectorXd b = rightHandSide(constraints, &keyPoints);
    const int m = freePoints();
    // d = C b, plus one step of iterative refinement (the force objective's triangular solves
    // leave ~κ(R)·u). Separable: the rows are (x, y, z) triples, b read as a rows/3 × 3 matrix.
    Eigen::VectorXd d(3 * m);
    if (separable_) {
        using Triples = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>;
        const Triples B(b.data(), b.size() / 3, 3);
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3>> D(d.data(), m, 3);
        D.noalias() = C1_ * B;
        const Eigen::Matrix<double, Eigen::Dynamic, 3> left = B - F1_ * D;
        D.noalias() += C1_ * left;
    } else {
        d.noalias() = C_ * b;
        const Eigen::VectorXd left = b - F_ * d;
        d.noalias() += C_ * left;
    }

    std::vector<Eigen::Vector3d> points = surface_.points();
    auto apply = [&](const Eigen::VectorXd& dd, std::vector<Eigen::Vector3d>& pts) {
        pts = surface_.points();
        for (int i = 0; i < m; ++i) {
            pts[static_cast<size_t>(free_[static_cast<size_t>(i)])] +=
                Eigen::Vector3d(dd[i], dd[m + i], dd[2 * m + i]);
        }
    };
    apply(d, points);
    auto build = [&](std::vector<Eigen::Vector3d> pts) {
        return Surface3d(surface_.degreeU(), surface_.degreeV(), surface_.knotsU(), surface_.knotsV(),
                         surface_.countU(), surface_.countV(), std::move(pts), surface_.weights());
    };
    Surface3d result = build(points);

    // Distance constraints (non-linear): chord-Newton on the factored rows (Gauss–Newton with the
    // Jacobian of the start kept, so each step is one more back-substitution): the other rows get
    // a zero right-hand side and stay met; the distance rows get the remaining length error.
    int steps = 0;
    const double lambda = options_.stiffness;
    auto lengthError = [&](const Surface3d& s, size_t c) {
        const SurfaceConstraint& k = constraints[c];
        const double now = (s.evaluate(k.uv2.x(), k.uv2.y()) - s.evaluate(k.uv.x(), k.uv.y())).norm();
        const double start = (surface_.evaluate(k.uv2.x(), k.uv2.y()) - surface_.evaluate(k.uv.x(), k.uv.y())).norm();
        return start + lambda * (k.distance - start) - now;
    };
    while (nonLinear_ && steps < kMaxDistanceSteps) {
        Eigen::VectorXd db = Eigen::VectorXd::Zero(F_.rows());
        double worst = 0.0;
        for (Eigen::Index k = 0; k < F_.rows(); ++k) {
            const size_t c = static_cast<size_t>(rowOwner_[static_cast<size_t>(k)]);
            if (constraints[c].type != SurfaceConstraintType::Distance) continue;
            db[k] = lengthError(result, c);
            worst = std::max(worst, std::abs(db[k]) / std::max(1.0, constraints[c].distance));
        }
        if (worst <= kDistanceRelativeTolerance) break;
        d.noalias() += C_ * db;
        apply(d, points);
        result = build(points);
        ++steps;
    }

    if (report) {
        const int r = rows();
        report->constraintRows = r;
        report->freePoints = m;
        report->rank = rank_;
        report->tooFewFreePoints = r > 3 * m;
        report->compromise = rank_ < r;
        report->keyPoints = std::move(keyPoints);
        report->gaussNewtonSteps = steps;
        report->boundCases = boundCases_;
        report->moved = 0;
        for (size_t i = 0; i < points.size(); ++i) report->moved += points[i] != surface_.points()[i] ? 1 : 0;
        report->residuals = constraintResiduals(surface_, result, factored_, constraints, keyUv_, keyT_, lambda);
        report->maxResidual = report->residuals.empty()
                                  ? 0.0
                                  : *std::max_element(report->residuals.begin(), report->residuals.end());
        report->message.clear();
        if (report->tooFewFreePoints) {
            report->message = std::to_string(r) + " constraint rows but only " + std::to_string(m) +
                              " free control points (x3 coordinates): least-squares compromise";
        } else if (report->compromise) {
            report->message = "constraints are dependent or contradictory (rank " + std::to_string(rank_) + " of " +
                              std::to_string(r) + " rows): least-squares compromise";
        }
        flagUnmet(surface_, constraints, *report);
        for (size_t c = 0; c < boundCases_.size() && report->message.empty(); ++c) {
            if (boundCases_[c] == BoundCase::Over) {
                report->message = at(c) + " lies outside the bound: it does not affect the surface (over-constrained, §6.3)";
            }
        }
    }
    return result;
}

Surface3d deformSurface(const Surface3d& surface, const std::vector<SurfaceConstraint>& constraints,
                        const DeformationOptions& options, DeformationReport* report)
{
    SurfaceDeformationSolver solver;
    solver.factor(surface, constraints, options);
    return solver.solve(constraints, report);
}

double forceChange(const Surface3d& before, const Surface3d& after)
{
    const int nu = before.countU(), nv = before.countV();
    double sum = 0.0;
    auto d = [&](int i, int j) { return Eigen::Vector3d(after.point(i, j) - before.point(i, j)); };
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            Eigen::Vector3d f = Eigen::Vector3d::Zero();
            if (i > 0) f += d(i, j) - d(i - 1, j);
            if (i + 1 < nu) f += d(i, j) - d(i + 1, j);
            if (j > 0) f += d(i, j) - d(i, j - 1);
            if (j + 1 < nv) f += d(i, j) - d(i, j + 1);
            sum += f.squaredNorm();
        }
    }
    return std::sqrt(sum);
}

}  // namespace sculptline::solvers::deformation
