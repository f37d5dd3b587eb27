#include "solvers/incidence/incidence_solve.h"

#include "solvers/bspline/basis.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "solvers/incidence/smoothing_functionals.h"
#include "solvers/regularization/lcurve_corner.h"
#include "solvers/regularization/mtsvd.h"

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

// A projected domain curve: a cubic with as many control points as its target (at least 4),
// fitted by least squares to this many feet per control point.
constexpr int kFeetPerControlPoint = 8;
// Residuals are measured at this many parameters per curve (dense against its spans).
constexpr int kResidualSamples = 257;

KnotVector clampedUniform(int count, int degree, double start, double end)
{
    KnotVector k(static_cast<size_t>(degree + 1), start);
    const int inner = count - degree - 1;
    for (int i = 1; i <= inner; ++i) k.push_back(start + (end - start) * i / (inner + 1));
    k.insert(k.end(), static_cast<size_t>(degree + 1), end);
    return k;
}

Surface3d withPoints(const Surface3d& s, const ControlMatrix& rows)
{
    std::vector<Eigen::Vector3d> points(static_cast<size_t>(rows.rows()));
    for (Eigen::Index i = 0; i < rows.rows(); ++i) points[static_cast<size_t>(i)] = rows.row(i).transpose();
    return Surface3d(s.degreeU(), s.degreeV(), s.knotsU(), s.knotsV(), s.countU(), s.countV(), std::move(points));
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
    const SurfaceProjector projector(surface);
    const int count = std::max(4, target.pointCount());
    const int samples = kFeetPerControlPoint * count;
    const double t0 = target.domainStart(), t1 = target.domainEnd();
    const KnotVector knots = clampedUniform(count, 3, t0, t1);
    Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(samples, count);
    Eigen::MatrixXd feet(samples, 2);
    for (int s = 0; s < samples; ++s) {
        const double t = t0 + (t1 - t0) * s / (samples - 1);
        const SurfaceProjection f = projector.project(target.evaluate(t));
        feet.row(s) << f.u, f.v;
        const int span = findSpan(3, knots, t);
        double n[4];
        basisFunctions(span, t, 3, knots, n);
        for (int a = 0; a <= 3; ++a) basis(s, span - 3 + a) = n[a];
    }
    const Eigen::MatrixXd fitted = basis.colPivHouseholderQr().solve(feet);
    // The control polygon inside the domain keeps the curve inside (convex hull).
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < count; ++i) {
        points.emplace_back(std::clamp(fitted(i, 0), surface.domainStart(Direction::U), surface.domainEnd(Direction::U)),
                            std::clamp(fitted(i, 1), surface.domainStart(Direction::V), surface.domainEnd(Direction::V)));
    }
    return Curve2d(3, knots, points);
}

IncidenceResult solveIncidence(const Surface3d& surface, const std::vector<IncidenceCurve>& curves,
                               const IncidenceOptions& options)
{
    if (curves.empty()) throw GeometryError("curves: at least one curve is needed");
    if (surface.isRational()) throw GeometryError("surface: a rational surface is not supported");
    const SurfaceStructure structure = SurfaceStructure::of(surface);
    IncidenceResult result{surface, 0, 0, 0, 0, 0, 0.0, 0.0, {}, {}};
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
        result.domains.push_back(r.domain);
        requests.push_back(std::move(r));
    }
    const IncidenceSystem system = stackIncidences(structure, requests);
    const Eigen::MatrixXd all = Eigen::MatrixXd(system.matrix);
    const int n = static_cast<int>(all.cols());
    const ControlMatrix f0 = surfacePointRows(surface);
    const Eigen::MatrixXd x0 = f0;
    const std::vector<int> hard = system.hardRows(), soft = system.softRows();

    // Fixed curves exactly: x = x_p + N z, x_p the least change from the present surface meeting
    // them, N a basis of their rows' null space; the rest is regularized in z.
    Eigen::MatrixXd xp = x0, basisN = Eigen::MatrixXd::Identity(n, n);
    if (!hard.empty()) {
        Eigen::MatrixXd c(static_cast<Eigen::Index>(hard.size()), n), d(static_cast<Eigen::Index>(hard.size()), 3);
        for (size_t r = 0; r < hard.size(); ++r) {
            c.row(static_cast<Eigen::Index>(r)) = all.row(hard[r]);
            d.row(static_cast<Eigen::Index>(r)) = system.rhs.row(hard[r]);
        }
        Eigen::BDCSVD<Eigen::MatrixXd> svd(c, Eigen::ComputeThinU | Eigen::ComputeFullV);
        // LAPACK's and numpy's rank cut-off: σ > max(m, n) ε σ1.
        svd.setThreshold(std::max(c.rows(), c.cols()) * std::numeric_limits<double>::epsilon());
        const int rank = static_cast<int>(svd.rank());
        xp = x0 + svd.solve(d - c * x0);
        basisN = svd.matrixV().rightCols(n - rank);
    }
    result.hardRows = static_cast<int>(hard.size());
    Eigen::MatrixXd x = xp;
    if (!soft.empty() && basisN.cols() > 0) {
        Eigen::MatrixXd s(static_cast<Eigen::Index>(soft.size()), n), b(static_cast<Eigen::Index>(soft.size()), 3);
        for (size_t r = 0; r < soft.size(); ++r) {
            s.row(static_cast<Eigen::Index>(r)) = all.row(soft[r]);
            b.row(static_cast<Eigen::Index>(r)) = system.rhs.row(soft[r]);
        }
        const Eigen::MatrixXd reduced = s * basisN;
        result.rows = static_cast<int>(reduced.rows());
        result.cols = static_cast<int>(reduced.cols());
        // The prior is the surface as it is (z = 0: x_p): TSVD changes it only along the k best
        // determined directions (seed 000 eqs. 3-4).
        const reg::CachedSvd svd(reduced);
        // Nothing asked of the soft rows (every curve keeps its image): the surface stays.
        const bool asked = (b - s * xp).norm() > 0.0;
        if (svd.rank() > 0 && asked) {
            const reg::ProjectedRhs rhs = reg::projectRhs(svd, b - s * xp);
            result.lcurve = reg::tsvdLCurve(svd, rhs);
            result.corner = reg::lcurveCorner(result.lcurve, reg::defaultCornerMethod(false)).k;
            result.k = options.k > 0 ? options.k : result.corner;
            if (result.k < 1 || result.k > svd.rank())
                throw std::invalid_argument("k: " + std::to_string(result.k) + " is outside 1.." + std::to_string(svd.rank()));
            Eigen::MatrixXd z;
            if (options.method == IncidenceMethod::Mtsvd) {
                // MTSVD at TSVD's k (the seed's default): of the solutions that keep the k
                // components, the one smoothest by L. With fixed curves L acts on the change in z
                // (their own least change x_p is zero when the surface already meets them).
                const Eigen::SparseMatrix<double> gram =
                    smoothingGram(structure, options.area, options.thinPlate, options.curvatureVariation);
                const Eigen::MatrixXd l = gramFactor(Eigen::MatrixXd(gram));
                const reg::MtsvdSolver mtsvd(svd, l * basisN);
                z = mtsvd.solution(rhs, result.k);
            } else {
                z = reg::tsvdSolution(svd, rhs, result.k);
            }
            x = xp + basisN * z;
        }
    }
    result.surface = withPoints(surface, x);
    for (size_t c = 0; c < curves.size(); ++c) {
        if (!curves[c].target && !curves[c].fixed) continue;
        const double gap = largestGap(result.surface, requests[c].domain, requests[c].request);
        double& into = curves[c].fixed ? result.fixedResidual : result.residual;
        into = std::max(into, gap);
    }
    return result;
}

}  // namespace sculptline::solvers::incidence
