#include "solvers/incidence/incidence_solve.h"

#include "solvers/bspline/basis.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "solvers/incidence/smoothing_functionals.h"
#include "solvers/regularization/lcurve_corner.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace sculptline::solvers::incidence {
namespace reg = regularization;
namespace {

// A projected domain curve is fitted by least squares to this many feet per control point of its
// target (of at least 4).
constexpr int kFeetPerControlPoint = 8;
// Residuals are measured at this many parameters per curve (dense against its spans).
constexpr int kResidualSamples = 257;

Surface3d withPoints(const Surface3d& s, const ControlMatrix& rows)
{
    std::vector<Eigen::Vector3d> points(static_cast<size_t>(rows.rows()));
    for (Eigen::Index i = 0; i < rows.rows(); ++i) points[static_cast<size_t>(i)] = rows.row(i).transpose();
    return Surface3d(s.degreeU(), s.degreeV(), s.knotsU(), s.knotsV(), s.countU(), s.countV(), std::move(points));
}

// The fixed curves' rows are met as closely as they can be, but their data are rarely consistent to
// round-off (a projected domain curve is a least-squares fit), and directions the rows hardly see (a
// control point whose basis function barely reaches the curve) would turn that inconsistency into
// huge control points. The discrepancy principle: keep the fewest singular directions whose dropped
// part of the change d − C x0 adds at most this fraction of the least-squares residual to it (in
// norm: ρ_k² ≤ ρ²(1 + s²), +0.5 % for s = 0.1), or kHardFloor when the rows are consistent.
constexpr double kHardSlack = 0.1;
// A soft direction is solved for when its singular value exceeds this fraction of the soft rows'
// size: 1e-8 bounds TSVD's amplification of the right-hand side at 1e8 of it, where round-off of
// the null-space basis (1e-16 relative) still stays below 1e-8 of the model.
constexpr double kSoftVisibility = 1e-8;
constexpr const char* kNoFreedom =
    "the fixed curves leave the surface no freedom where the other curves are (a surface with more control points would have some)";
// Absolute floor of that dropped part (model units): far below what a display or a printer shows, far
// above round-off for model sizes up to metres.
constexpr double kHardFloor = 1e-9;

int hardRank(const Eigen::BDCSVD<Eigen::MatrixXd>& svd, const Eigen::MatrixXd& change)
{
    const int rank = static_cast<int>(svd.rank());
    const Eigen::MatrixXd beta = svd.matrixU().leftCols(rank).transpose() * change;
    const double total = change.squaredNorm();
    const double seen = beta.squaredNorm();
    const double floor2 = std::max(0.0, total - seen);  // ρ² of the full-rank least-squares solution
    const double allowed = kHardSlack * kHardSlack * floor2 + kHardFloor * kHardFloor;
    double dropped = seen;
    for (int k = 0; k < rank; ++k) {
        if (dropped <= allowed) return k;
        dropped -= beta.row(k).squaredNorm();
    }
    return rank;
}

double largestGap(const Surface3d& s, const Curve2d& g, const Curve3d& h)
{
    double worst = 0.0;
    for (int k = 0; k < kResidualSamples; ++k) {
        const double t = g.domainStart() + (g.domainEnd() - g.domainStart()) * k / (kResidualSamples - 1);
        const Eigen::Vector2d uv = g.evaluate(t);
        worst = std::max(worst, (s.evaluate(uv.x(), uv.y()) - h.evaluate(t)).norm());
    }
    return worst;
}

}  // namespace

Curve2d projectedDomain(const Surface3d& surface, const Curve3d& target)
{
    // G takes the target's own degree and knots (a closed target's clamped form): where the target
    // lies on the surface and the surface is an affine map of its domain (a flat sheet), G is then
    // its exact pre-image, and a fixed curve's rows are consistent to round-off.
    const Curve3d open = target.isClosed() ? target.clamped() : target;
    const int degree = open.degree();
    const KnotVector& knots = open.knots();
    const int count = open.pointCount();
    const SurfaceProjector projector(surface);
    const int samples = kFeetPerControlPoint * std::max(4, count);
    const double t0 = open.domainStart(), t1 = open.domainEnd();
    Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(samples, count);
    Eigen::MatrixXd feet(samples, 2);
    std::vector<double> n(static_cast<size_t>(degree + 1));
    for (int s = 0; s < samples; ++s) {
        const double t = t0 + (t1 - t0) * s / (samples - 1);
        const SurfaceProjection f = projector.project(open.evaluate(t));
        feet.row(s) << f.u, f.v;
        const int span = findSpan(degree, knots, t);
        basisFunctions(span, t, degree, knots, n.data());
        for (int a = 0; a <= degree; ++a) basis(s, span - degree + a) = n[static_cast<size_t>(a)];
    }
    const Eigen::MatrixXd fitted = basis.colPivHouseholderQr().solve(feet);
    // The control polygon inside the domain keeps the curve inside (convex hull).
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < count; ++i) {
        points.emplace_back(std::clamp(fitted(i, 0), surface.domainStart(Direction::U), surface.domainEnd(Direction::U)),
                            std::clamp(fitted(i, 1), surface.domainStart(Direction::V), surface.domainEnd(Direction::V)));
    }
    return Curve2d(degree, knots, points);
}

struct IncidenceSolver::State {
    explicit State(const Surface3d& prior) : surface(prior) {}
    Surface3d surface;  // the prior
    IncidenceOptions options;
    std::vector<Curve2d> domains;
    std::vector<bool> fixed, hasTarget;
    std::vector<int> degrees;
    std::vector<KnotVector> knots;
    IncidenceSystem system;
    std::vector<SparseRows> compatibility;  // per curve: its target's points -> its rows' right-hand side
    std::vector<int> hard, soft;
    Eigen::MatrixXd x0, cPlus, basisN;  // prior (n×3), the hard rows' pseudo-inverse, their null basis
    SparseRows cSparse, sSparse;         // the hard and the soft rows (a drag event's products)
    // Per curve without a target: its image on the prior, what it keeps (made once, at factor()).
    std::vector<std::optional<Curve3d>> images;
    std::unique_ptr<reg::CachedSvd> svd;     // of S N
    Eigen::MatrixXd correction;               // MTSVD's P at k (identity for TSVD), on z
    Eigen::MatrixXd uk, lift;                 // U_k, and N P V_k Σ_k⁻¹: x = x_p + lift (U_kᵀ b)
    int k = 0, corner = 0;
    reg::LCurve lcurve;
    bool solved = false;  // false: nothing to regularize (no soft rows, no freedom, or nothing asked)

    // The stacked right-hand side for `targets` (each curve's request: its target, or its present image).
    Eigen::MatrixXd rhs(const std::vector<Curve3d>& requests) const
    {
        Eigen::MatrixXd b(system.matrix.rows(), 3);
        for (const RowBlock& block : system.blocks) {
            if (block.kind == RowBlock::Kind::Curve) {
                const Curve3d request = requests[static_cast<size_t>(block.curve)].isClosed()
                                            ? requests[static_cast<size_t>(block.curve)].clamped()
                                            : requests[static_cast<size_t>(block.curve)];
                ControlMatrix points(request.pointCount(), 3);
                for (int i = 0; i < request.pointCount(); ++i) points.row(i) = request.points()[static_cast<size_t>(i)].transpose();
                b.middleRows(block.firstRow, block.rowCount) = compatibility[static_cast<size_t>(block.curve)] * points;
            } else {
                // A crossing: the fixed request's point there, else the two requests' mean (as stacked).
                const size_t a = static_cast<size_t>(block.curve), o = static_cast<size_t>(block.otherCurve);
                const Eigen::Vector3d pa = requests[a].evaluate(block.t), pb = requests[o].evaluate(block.tOther);
                b.row(block.firstRow) = (fixed[a] ? pa : fixed[o] ? pb : Eigen::Vector3d(0.5 * (pa + pb))).transpose();
            }
        }
        return b;
    }

    std::vector<Curve3d> requests(const std::vector<IncidenceCurve>& curves) const
    {
        std::vector<Curve3d> out;
        for (size_t c = 0; c < curves.size(); ++c)
            out.push_back(curves[c].target ? *curves[c].target : *images[c]);
        return out;
    }
};

IncidenceSolver::IncidenceSolver() = default;
IncidenceSolver::~IncidenceSolver() = default;
IncidenceSolver::IncidenceSolver(IncidenceSolver&&) noexcept = default;
IncidenceSolver& IncidenceSolver::operator=(IncidenceSolver&&) noexcept = default;

void IncidenceSolver::factor(const Surface3d& surface, const std::vector<IncidenceCurve>& curves, const IncidenceOptions& options)
{
    state_.reset();
    if (curves.empty()) throw GeometryError("curves: at least one curve is needed");
    if (surface.isRational()) throw GeometryError("surface: a rational surface is not supported");
    auto st = std::make_unique<State>(surface);
    st->options = options;
    const SurfaceStructure structure = SurfaceStructure::of(surface);
    std::vector<CurveRequest> requests;
    for (size_t c = 0; c < curves.size(); ++c) {
        const std::string at = "curves[" + std::to_string(c) + "]";
        const IncidenceCurve& in = curves[c];
        if (!in.domain && !in.target) throw GeometryError(at + ": a domain curve or a target curve is needed");
        const Curve2d domain = in.domain ? *in.domain : projectedDomain(surface, *in.target);
        if (in.target && (std::abs(in.target->domainStart() - domain.domainStart()) > 1e-12 ||
                          std::abs(in.target->domainEnd() - domain.domainEnd()) > 1e-12))
            throw GeometryError(at + ".target: must be parameterized over its domain curve's [" +
                                std::to_string(domain.domainStart()) + ", " + std::to_string(domain.domainEnd()) + "]");
        // Without a target the curve keeps its present image.
        CurveRequest r{domain, in.target ? *in.target : applyComposition(compose(structure, domain), surface), in.fixed};
        st->domains.push_back(domain);
        st->fixed.push_back(in.fixed);
        st->hasTarget.push_back(in.target.has_value());
        st->degrees.push_back(in.target ? in.target->degree() : -1);
        st->knots.push_back(in.target ? in.target->knots() : KnotVector{});
        st->images.push_back(in.target ? std::nullopt : std::optional<Curve3d>(r.request));
        requests.push_back(std::move(r));
    }
    st->system = stackIncidences(structure, requests);
    for (size_t c = 0; c < requests.size(); ++c) {
        const Curve3d request = requests[c].request.isClosed() ? requests[c].request.clamped() : requests[c].request;
        st->compatibility.push_back(compatibilityMatrix(request.degree(), request.knots(), st->system.compositions[c].space));
    }
    const Eigen::MatrixXd all = Eigen::MatrixXd(st->system.matrix);
    const int n = static_cast<int>(all.cols());
    st->x0 = surfacePointRows(surface);
    st->hard = st->system.hardRows();
    st->soft = st->system.softRows();
    const Eigen::MatrixXd b = st->rhs(st->requests(curves));
    // The per-event right-hand side mirrors stackIncidences' (compatibility products, crossing
    // targets); the two must agree, or solve() would answer another question than factor().
    if ((b - Eigen::MatrixXd(st->system.rhs)).norm() > 1e-9 * std::max(1.0, b.norm()))
        throw std::logic_error("incidence: the kept right-hand side differs from the stacked one");

    // Fixed curves exactly: x = x_p + N z, x_p the least change from the prior meeting them
    // (C⁺ kept: a moved fixed curve costs one product), N a basis of their rows' null space.
    st->basisN = Eigen::MatrixXd::Identity(n, n);
    Eigen::MatrixXd xp = st->x0;
    if (!st->hard.empty()) {
        Eigen::MatrixXd c(static_cast<Eigen::Index>(st->hard.size()), n);
        for (size_t r = 0; r < st->hard.size(); ++r) c.row(static_cast<Eigen::Index>(r)) = all.row(st->hard[r]);
        Eigen::BDCSVD<Eigen::MatrixXd> svd(c, Eigen::ComputeThinU | Eigen::ComputeFullV);
        // LAPACK's and numpy's rank cut-off: σ > max(m, n) ε σ1.
        svd.setThreshold(std::max(c.rows(), c.cols()) * std::numeric_limits<double>::epsilon());
        st->cSparse = c.sparseView();
        Eigen::MatrixXd d(static_cast<Eigen::Index>(st->hard.size()), 3);
        for (size_t i = 0; i < st->hard.size(); ++i) d.row(static_cast<Eigen::Index>(i)) = b.row(st->hard[i]);
        // N: every direction the rows see is kept from the soft solve (their numerical rank); C⁺:
        // only the directions the discrepancy principle keeps (the rest stay at the prior).
        const int rank = static_cast<int>(svd.rank());
        const int r = hardRank(svd, d - st->cSparse * st->x0);
        st->cPlus = svd.matrixV().leftCols(r) * svd.singularValues().head(r).cwiseInverse().asDiagonal() *
                    svd.matrixU().leftCols(r).transpose();
        st->basisN = svd.matrixV().rightCols(n - rank);
        xp = st->x0 + st->cPlus * (d - st->cSparse * st->x0);
    }
    st->correction.resize(0, 0);
    if (!st->soft.empty() && st->basisN.cols() > 0) {
        Eigen::MatrixXd soft(static_cast<Eigen::Index>(st->soft.size()), n);
        Eigen::MatrixXd bs(static_cast<Eigen::Index>(st->soft.size()), 3);
        for (size_t r = 0; r < st->soft.size(); ++r) {
            soft.row(static_cast<Eigen::Index>(r)) = all.row(st->soft[r]);
            bs.row(static_cast<Eigen::Index>(r)) = b.row(st->soft[r]);
        }
        st->sSparse = soft.sparseView();
        const Eigen::MatrixXd reduced = soft * st->basisN;
        st->svd = std::make_unique<reg::CachedSvd>(reduced);
        // Nothing asked of the soft rows (every curve keeps its image): the surface stays.
        const Eigen::MatrixXd bRed = bs - st->sSparse * xp;
        if (st->svd->rank() > 0 && bRed.norm() > 0.0) {
            // The prior is the surface as it is (z = 0: x_p): TSVD changes it only along the k best
            // determined directions (seed 000 eqs. 3-4).
            const reg::ProjectedRhs rhs = reg::projectRhs(*st->svd, bRed);
            st->lcurve = reg::tsvdLCurve(*st->svd, rhs);
            // Directions the soft rows see only at round-off of their own size (after the fixed
            // curves took the rest: a fixed rim around a coarse net) are not solved for: TSVD would
            // amplify nothing into huge control points.
            const double scale = soft.norm();  // >= σ1 of the soft rows
            int visible = 0;
            while (visible < st->svd->rank() && st->svd->singularValues()(visible) > kSoftVisibility * scale) ++visible;
            if (visible == 0) throw GeometryError(kNoFreedom);
            if (visible < st->lcurve.rho.size()) {
                st->lcurve.rho.conservativeResize(visible);
                st->lcurve.eta.conservativeResize(visible);
            }
            st->corner = reg::lcurveCorner(st->lcurve, reg::defaultCornerMethod(false)).k;
            st->k = options.k > 0 ? options.k : st->corner;
            if (st->k < 1 || st->k > visible)
                throw std::invalid_argument("k: " + std::to_string(st->k) + " is outside 1.." + std::to_string(visible));
            const int nz = static_cast<int>(reduced.cols());
            if (options.method == IncidenceMethod::Mtsvd && st->k < nz) {
                // MTSVD at TSVD's k (the seed's default): of the solutions that keep the k
                // components, the one smoothest by L: z = P z_k with P = I − W (L W)⁺ L, W = V_{k+1}.
                // (With fixed curves L acts on the change in z; their own least change x_p is zero
                // when the surface already meets them.) The rank of L W is cut at 1e-10 of its
                // largest pivot: a direction L hardly sees is left alone, not amplified.
                const Eigen::SparseMatrix<double> gram =
                    smoothingGram(structure, options.area, options.thinPlate, options.curvatureVariation);
                const Eigen::MatrixXd l = gramFactor(Eigen::MatrixXd(gram)) * st->basisN;
                Eigen::MatrixXd vFull(nz, nz);
                vFull << st->svd->v(), st->svd->nullBasis();
                const Eigen::MatrixXd w = vFull.rightCols(nz - st->k);
                Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
                cod.setThreshold(1e-10);
                cod.compute(l * w);
                st->correction = Eigen::MatrixXd::Identity(nz, nz) - w * cod.solve(l);
            }
            // The two products of a drag event, prepared: U_kᵀ b, and N P V_k Σ_k⁻¹ times it.
            st->uk = st->svd->u().leftCols(st->k);
            Eigen::MatrixXd vk = st->svd->v().leftCols(st->k) * st->svd->singularValues().head(st->k).cwiseInverse().asDiagonal();
            if (st->correction.size() > 0) vk = st->correction * vk;
            st->lift = st->basisN * vk;
            st->solved = true;
        }
    }
    state_ = std::move(st);
}

bool IncidenceSolver::fits(const std::vector<IncidenceCurve>& curves) const
{
    if (!state_ || curves.size() != state_->domains.size()) return false;
    for (size_t c = 0; c < curves.size(); ++c) {
        if (curves[c].target.has_value() != state_->hasTarget[c] || curves[c].fixed != state_->fixed[c]) return false;
        if (curves[c].target && (curves[c].target->degree() != state_->degrees[c] || curves[c].target->knots() != state_->knots[c] ||
                                 curves[c].target->isRational()))
            return false;
    }
    return true;
}

IncidenceResult IncidenceSolver::solve(const std::vector<IncidenceCurve>& curves) const
{
    if (!fits(curves)) throw std::invalid_argument("curves: not the layout the solver was factored for");
    const State& st = *state_;
    const std::vector<Curve3d> requests = st.requests(curves);
    const Eigen::MatrixXd b = st.rhs(requests);
    Eigen::MatrixXd xp = st.x0;
    if (!st.hard.empty()) {
        Eigen::MatrixXd d(static_cast<Eigen::Index>(st.hard.size()), 3);
        for (size_t i = 0; i < st.hard.size(); ++i) d.row(static_cast<Eigen::Index>(i)) = b.row(st.hard[i]);
        xp = st.x0 + st.cPlus * (d - st.cSparse * st.x0);
    }
    Eigen::MatrixXd x = xp;
    if (st.solved) {
        Eigen::MatrixXd bs(static_cast<Eigen::Index>(st.soft.size()), 3);
        for (size_t r = 0; r < st.soft.size(); ++r) bs.row(static_cast<Eigen::Index>(r)) = b.row(st.soft[r]);
        // The two products: U_kᵀ b, then N P V_k Σ_k⁻¹ of it (TSVD with the prior z = 0, MTSVD's
        // correction P kept; tsvd.h's x_k = Σ_{i≤k} (u_iᵀ b / σ_i) v_i).
        x = xp + st.lift * (st.uk.transpose() * (bs - st.sSparse * xp));
    }
    IncidenceResult result{withPoints(st.surface, x), st.k, st.corner, 0, 0, static_cast<int>(st.hard.size()), 0.0, 0.0, st.lcurve, st.domains};
    if (st.svd) {
        result.rows = st.svd->rows();
        result.cols = st.svd->cols();
    }
    for (size_t c = 0; c < curves.size(); ++c) {
        if (!curves[c].target && !curves[c].fixed) continue;
        const double gap = largestGap(result.surface, st.domains[c], requests[c]);
        double& into = curves[c].fixed ? result.fixedResidual : result.residual;
        into = std::max(into, gap);
    }
    return result;
}

IncidenceResult solveIncidence(const Surface3d& surface, const std::vector<IncidenceCurve>& curves,
                               const IncidenceOptions& options)
{
    IncidenceSolver solver;
    solver.factor(surface, curves, options);
    return solver.solve(curves);
}

}  // namespace sculptline::solvers::incidence
