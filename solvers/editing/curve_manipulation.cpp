#include "solvers/editing/curve_manipulation.h"

#include "solvers/bspline/geometry_error.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace sculptline::solvers::editing {
namespace {

// A pivot of the QR of Fᵀ below this fraction of the largest one marks a constraint that depends
// on the others. F's entries are basis-function values and derivatives, exact to ~1e-15 relative,
// so 1e-10 is far above round-off yet far below any constraint a person would set on purpose;
// solving through such a pivot would amplify the targets by 1e10 instead of compromising.
constexpr double kRankRelativeTolerance = 1e-10;

template <int Dim>
int uniqueCount(const BSplineCurve<Dim>& c)
{
    return c.isClosed() ? c.pointCount() - c.degree() : c.pointCount();
}

// Adds the coefficients of the k-th derivative of C at u to `row` (unique indices; a closed
// curve's wrapped basis functions fold onto the point they repeat).
//
// Rational curves, weights held fixed: C(u) = Σ R_i(u) P_i with R_i = w_i N_i / W, W = Σ w_j N_j
// (The NURBS Book eq. 4.2). R_i and its derivatives depend on u and the weights only, so every
// constraint stays exactly linear in the Cartesian control points: there is nothing to linearize
// (the linearization would be needed only if the weights moved too; C is then bilinear in
// (w_i P_i, w_i)). Derivatives of the quotient A_i / W with A_i = w_i N_i:
// R' = (A' - R W') / W, R'' = (A'' - 2 R' W' - R W'') / W.
template <int Dim>
void addBasisRow(const BSplineCurve<Dim>& curve, double u, int k, double sign, Eigen::VectorXd& row)
{
    if (!std::isfinite(u)) throw GeometryError("constraints: parameter u is not a finite number");
    if (k > 2) throw GeometryError("constraints: derivatives above the second are not supported");
    const double un = curve.normalizeParameter(u);
    const int p = curve.degree();
    const int span = findSpan(p, curve.knots(), un);
    const Eigen::MatrixXd ders = basisDerivatives(span, un, p, k, curve.knots());
    const int n = uniqueCount(curve);
    if (!curve.isRational()) {
        for (int j = 0; j <= p; ++j) row[(span - p + j) % n] += sign * ders(k, j);
        return;
    }
    double W[3] = {0.0, 0.0, 0.0};
    for (int j = 0; j <= p; ++j) {
        for (int d = 0; d <= k; ++d) W[d] += curve.weight(span - p + j) * ders(d, j);
    }
    for (int j = 0; j <= p; ++j) {
        const double w = curve.weight(span - p + j);
        const double r0 = w * ders(0, j) / W[0];
        const double r1 = k >= 1 ? (w * ders(1, j) - r0 * W[1]) / W[0] : 0.0;
        const double r2 = k >= 2 ? (w * ders(2, j) - 2.0 * r1 * W[1] - r0 * W[2]) / W[0] : 0.0;
        row[(span - p + j) % n] += sign * (k == 0 ? r0 : k == 1 ? r1 : r2);
    }
}

template <int Dim>
std::vector<typename BSplineCurve<Dim>::Point> uniquePoints(const BSplineCurve<Dim>& c)
{
    const auto& pts = c.points();
    return {pts.begin(), pts.begin() + uniqueCount(c)};
}

template <int Dim>
BSplineCurve<Dim> withUniquePoints(const BSplineCurve<Dim>& c, std::vector<typename BSplineCurve<Dim>::Point> pts)
{
    if (c.isClosed()) {
        for (int i = 0; i < c.degree(); ++i) pts.push_back(pts[i]);
    }
    return BSplineCurve<Dim>(c.degree(), c.knots(), std::move(pts), c.weights(), c.isClosed());
}

}  // namespace

template <int Dim>
Eigen::VectorXd constraintRow(const BSplineCurve<Dim>& curve, const CurveConstraint<Dim>& c)
{
    Eigen::VectorXd row = Eigen::VectorXd::Zero(uniqueCount(curve));
    switch (c.type) {
        case ConstraintType::Position:
            addBasisRow(curve, c.u, 0, 1.0, row);
            break;
        case ConstraintType::Tangent:
            addBasisRow(curve, c.u, 1, 1.0, row);
            break;
        case ConstraintType::Curvature:
            addBasisRow(curve, c.u, 2, 1.0, row);
            break;
        case ConstraintType::Distance:
            addBasisRow(curve, c.u2, 0, 1.0, row);
            addBasisRow(curve, c.u, 0, -1.0, row);
            break;
    }
    return row;
}

template <int Dim>
CurveManipulationSolver<Dim>::CurveManipulationSolver(Curve curve, std::vector<CurveConstraint<Dim>> constraints,
                                                      std::vector<int> blocked)
    : curve_(std::move(curve)), constraints_(std::move(constraints))
{
    const int n = uniqueCount(curve_);
    std::vector<bool> isBlocked(n, false);
    for (int b : blocked) {
        if (b < 0 || b >= n) {
            throw GeometryError("blocked: index " + std::to_string(b) + " outside [0, " + std::to_string(n - 1) + "]");
        }
        isBlocked[b] = true;
    }
    for (int i = 0; i < n; ++i) {
        if (!isBlocked[i]) free_.push_back(i);
    }

    // Preprocessing stage (thesis §6.1): F restricted to the free points, and C with d = C b.
    const int rows = static_cast<int>(constraints_.size());
    const int m = static_cast<int>(free_.size());
    F_.resize(rows, m);
    const auto pts = uniquePoints(curve_);
    current_.resize(rows);
    for (int j = 0; j < rows; ++j) {
        const Eigen::VectorXd full = constraintRow(curve_, constraints_[j]);
        Point v = Point::Zero();
        for (int i = 0; i < n; ++i) v += full[i] * pts[i];
        current_[j] = v;
        for (int i = 0; i < m; ++i) F_(j, i) = full[free_[i]];
    }
    C_ = Eigen::MatrixXd::Zero(m, rows);
    if (rows == 0 || m == 0) return;

    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(F_.transpose());
    qr.setThreshold(kRankRelativeTolerance);
    rank_ = static_cast<int>(qr.rank());
    if (rank_ == 0) return;
    const Eigen::MatrixXd q1 = qr.householderQ() * Eigen::MatrixXd::Identity(m, rank_);
    const Eigen::MatrixXd a =
        qr.matrixR().topRows(rank_).template triangularView<Eigen::Upper>().toDenseMatrix().transpose();
    // a (rows × rank) has full column rank: its least-squares solution operator, column by column.
    const Eigen::MatrixXd aPlus = a.householderQr().solve(Eigen::MatrixXd::Identity(rows, rows));
    C_ = q1 * (aPlus * qr.colsPermutation().transpose());
}

template <int Dim>
void CurveManipulationSolver<Dim>::displacements(const std::vector<Point>& targets, Displacements& d) const
{
    const int rows = static_cast<int>(constraints_.size());
    if (static_cast<int>(targets.size()) != rows) {
        throw GeometryError("constraints: expected " + std::to_string(rows) + " targets, got " +
                            std::to_string(targets.size()));
    }
    Eigen::Matrix<double, Eigen::Dynamic, Dim> b(rows, Dim);
    for (int j = 0; j < rows; ++j) b.row(j) = (targets[j] - current_[j]).transpose();
    d.noalias() = C_ * b;
}

template <int Dim>
BSplineCurve<Dim> CurveManipulationSolver<Dim>::solve(const std::vector<Point>& targets,
                                                      ManipulationReport* report) const
{
    for (const Point& t : targets) {
        if (!t.allFinite()) throw GeometryError("constraints: value is not a finite number");
    }
    Displacements d;
    displacements(targets, d);
    auto pts = uniquePoints(curve_);
    for (size_t i = 0; i < free_.size(); ++i) pts[free_[i]] += d.row(static_cast<Eigen::Index>(i)).transpose();
    Curve result = withUniquePoints(curve_, std::move(pts));
    if (report) {
        const int rows = static_cast<int>(constraints_.size());
        report->constraintRows = rows;
        report->freePoints = static_cast<int>(free_.size());
        report->rank = rank_;
        report->tooFewFreePoints = rows > report->freePoints;
        report->compromise = rank_ < rows;
        report->residuals.assign(rows, 0.0);
        const Eigen::Matrix<double, Eigen::Dynamic, Dim> fd = F_ * d;
        report->maxResidual = 0.0;
        for (int j = 0; j < rows; ++j) {
            const Point reached = current_[j] + fd.row(j).transpose();
            report->residuals[j] = (reached - targets[j]).norm();
            report->maxResidual = std::max(report->maxResidual, report->residuals[j]);
        }
        report->message.clear();
        if (report->tooFewFreePoints) {
            report->message = std::to_string(rows) + " constraints but only " + std::to_string(report->freePoints) +
                              " free control points: insert knots near the constraints (insertKnotsNearConstraints)";
        } else if (report->compromise) {
            report->message = "constraints are dependent or contradictory (rank " + std::to_string(rank_) + " of " +
                              std::to_string(rows) + "): least-squares compromise";
        }
    }
    return result;
}

template <int Dim>
BSplineCurve<Dim> constrainCurve(const BSplineCurve<Dim>& curve, const std::vector<CurveConstraint<Dim>>& constraints,
                                 const std::vector<int>& blocked, ManipulationReport* report)
{
    CurveManipulationSolver<Dim> solver(curve, constraints, blocked);
    std::vector<typename BSplineCurve<Dim>::Point> targets;
    for (const auto& c : constraints) targets.push_back(c.value);
    return solver.solve(targets, report);
}

template <int Dim>
BSplineCurve<Dim> insertKnotsNearConstraints(const BSplineCurve<Dim>& curve,
                                             const std::vector<CurveConstraint<Dim>>& constraints, int rounds)
{
    BSplineCurve<Dim> result = curve;
    for (int r = 0; r < rounds; ++r) {
        std::vector<double> mids;
        auto addMid = [&](double u) {
            const double un = result.normalizeParameter(u);
            const int span = findSpan(result.degree(), result.knots(), un);
            mids.push_back(0.5 * (result.knots()[span] + result.knots()[span + 1]));
        };
        for (const auto& c : constraints) {
            addMid(c.u);
            if (c.type == ConstraintType::Distance) addMid(c.u2);
        }
        std::sort(mids.begin(), mids.end());
        mids.erase(std::unique(mids.begin(), mids.end()), mids.end());
        result = result.refine(mids);
    }
    return result;
}

#define SCULPTLINE_INSTANTIATE(D)                                                                              \
    template class CurveManipulationSolver<D>;                                                                 \
    template Eigen::VectorXd constraintRow<D>(const BSplineCurve<D>&, const CurveConstraint<D>&);              \
    template BSplineCurve<D> constrainCurve<D>(const BSplineCurve<D>&, const std::vector<CurveConstraint<D>>&, \
                                               const std::vector<int>&, ManipulationReport*);                  \
    template BSplineCurve<D> insertKnotsNearConstraints<D>(const BSplineCurve<D>&,                             \
                                                           const std::vector<CurveConstraint<D>>&, int);
SCULPTLINE_INSTANTIATE(2)
SCULPTLINE_INSTANTIATE(3)
#undef SCULPTLINE_INSTANTIATE

}  // namespace sculptline::solvers::editing
