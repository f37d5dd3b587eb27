#include "solvers/surfaces/fill_tangents.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/math_constants.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace sculptline::solvers::surfaces {

namespace {

using Vec3 = Eigen::Vector3d;

// Gauss-Newton steps for a point on the surface: quadratic convergence reaches round-off in 3-5.
constexpr int kNewtonSteps = 12;
// Relative regularization of the normal equations: small enough that the constraints are met to
// ~1e-12 of their scale, large enough to make the system definite (the components of δ the
// constraints leave free are damped to zero: the least change).
constexpr double kRegularization = 1e-12;
// A tracked point this close (relative to the reference's size) is on the surface: round-off of
// evaluating a point of a curve that lies on it.
constexpr double kOnSurface = 1e-9;
// Newton stops once the point is this close (relative): round-off of evaluating the surface.
constexpr double kConverged = 1e-14;

// The grid index of point r (0 = on the side, 1 = next inner row) at position i along patch side `side`.
size_t gridIndex(int side, int i, int r, int nu, int nv)
{
    switch (side) {
    case 0: return static_cast<size_t>(i) * nv + r;
    case 1: return static_cast<size_t>(nu - 1 - r) * nv + i;
    case 2: return static_cast<size_t>(i) * nv + (nv - 1 - r);
    default: return static_cast<size_t>(r) * nv + i;
    }
}

Eigen::Vector2d patchParams(int side, double t)
{
    switch (side) {
    case 0: return {t, 0.0};
    case 1: return {1.0, t};
    case 2: return {t, 1.0};
    default: return {0.0, t};
    }
}

}  // namespace

ReferenceTracker::ReferenceTracker(const Surface3d& reference) : reference_(std::make_shared<Surface3d>(reference))
{
    Eigen::AlignedBox3d box;
    for (const Vec3& p : reference.points()) box.extend(p);
    size_ = std::max(box.diagonal().norm(), std::numeric_limits<double>::min());
}

double ReferenceTracker::refine(const Vec3& x, Eigen::Vector2d& uv, Vec3& normal) const
{
    const Surface3d& s = *reference_;
    const Eigen::Vector2d lo(s.domainStart(Direction::U), s.domainStart(Direction::V));
    const Eigen::Vector2d hi(s.domainEnd(Direction::U), s.domainEnd(Direction::V));
    double dist = std::numeric_limits<double>::infinity();
    for (int it = 0; it <= kNewtonSteps; ++it) {
        const auto d = s.derivatives(uv.x(), uv.y(), 1);
        const Vec3 r = d[0][0] - x;
        dist = r.norm();
        const Vec3 n = d[1][0].cross(d[0][1]);
        normal = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
        if (dist <= kConverged * size_ || it == kNewtonSteps) break;
        Eigen::Matrix<double, 3, 2> J;
        J << d[1][0], d[0][1];
        const Eigen::Matrix2d JtJ = J.transpose() * J;
        if (!(std::abs(JtJ.determinant()) > 0.0)) break;
        const Eigen::Vector2d next = (uv - JtJ.ldlt().solve(J.transpose() * r)).cwiseMax(lo).cwiseMin(hi);
        if (!next.allFinite() || (next - uv).norm() <= 1e-15 * (hi - lo).norm()) break;
        uv = next;
    }
    // At a collapsed edge of the reference the first derivatives do not give the normal.
    if (normal.squaredNorm() < 0.5) normal = reference_->normal(uv.x(), uv.y());
    return dist;
}

std::vector<Eigen::Vector2d> ReferenceTracker::locate(const std::vector<Vec3>& points, double* worst,
                                                      std::vector<Vec3>* normals)
{
    std::vector<Eigen::Vector2d> out;
    if (normals) normals->clear();
    double far = 0.0;
    const bool warm = last_.size() == points.size();
    for (size_t k = 0; k < points.size(); ++k) {
        const Vec3& x = points[k];
        Eigen::Vector2d uv = warm ? last_[k] : out.empty() ? Eigen::Vector2d::Zero() : out.back();
        Vec3 normal = Vec3::Zero();
        double dist = std::numeric_limits<double>::infinity();
        if (warm || !out.empty()) dist = refine(x, uv, normal);
        // Tracking lands on the nearest local minimum; a distance above round-off means it lost
        // the curve (a fold of the reference), so search globally.
        if (!(dist <= kOnSurface * size_)) {
            if (!projector_) projector_ = std::make_shared<SurfaceProjector>(*reference_);
            const SurfaceProjection p = projector_->project(x);
            if (p.distance < dist) {
                uv = {p.u, p.v};
                dist = refine(x, uv, normal);
            }
        }
        far = std::max(far, dist);
        out.push_back(uv);
        if (normals) normals->push_back(normal);
    }
    last_ = out;
    if (worst) *worst = far;
    return out;
}

Vec3 ReferenceTracker::normal(const Eigen::Vector2d& uv) const { return reference_->normal(uv.x(), uv.y()); }

void locateSamples(G1Side& g, const Curve3d& side, const CurveLayout& layout, double tolerance)
{
    g.samples.assign(1, 0.0);
    for (size_t k = 0; k + 1 < layout.knots.size(); ++k) {
        const double a = layout.knots[k], b = layout.knots[k + 1];
        if (!(b > a)) continue;
        for (int j = 0; j < kG1SamplesPerSpan; ++j) g.samples.push_back(a + (b - a) * (j + 0.5) / kG1SamplesPerSpan);
    }
    g.samples.push_back(1.0);
    std::vector<Vec3> points;
    for (double t : g.samples) points.push_back(side.evaluate(t));
    double worst = 0.0;
    g.tracker->locate(points, &worst, &g.normals);
    if (!(worst <= tolerance))
        throw GeometryError("tangents[" + std::to_string(g.tangentIndex) + "]: curves[" + std::to_string(g.curveIndex) +
                            "] does not lie on its reference surface: up to " + std::to_string(worst) +
                            " away (tolerance " + std::to_string(tolerance) + ")");
}

void applyG1(std::vector<Vec3>& pts, int nu, int nv, const std::array<CurveLayout, 2>& layouts,
             const std::vector<G1Side>& sides)
{
    // Unknowns: the inner-row points of every G1 side, except those on the patch boundary.
    std::vector<int> slot(pts.size(), -1);
    int unknowns = 0;
    for (const G1Side& g : sides) {
        const int len = g.side % 2 == 0 ? nu : nv;
        for (int i = 1; i + 1 < len; ++i) {
            const size_t q = gridIndex(g.side, i, 1, nu, nv);
            if (slot[q] < 0) slot[q] = unknowns++;
        }
    }
    if (unknowns == 0) return;
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> rhs;
    for (const G1Side& g : sides) {
        const CurveLayout& layout = layouts[g.side % 2 == 0 ? 0 : 1];
        const int p = layout.degree;
        std::vector<double> N(p + 1);
        // The ends are corners, fixed by the neighbouring boundaries (checked by the caller).
        for (size_t k = 1; k + 1 < g.samples.size(); ++k) {
            const double t = g.samples[k];
            const Vec3& n = g.normals[k];
            if (n.squaredNorm() < 0.5) continue;  // reference normal undefined here
            const int span = findSpan(p, layout.knots, t);
            basisFunctions(span, t, p, layout.knots, N.data());
            // The cross derivative at the side is c·Σ N_i (P_i,1 - P_i,0) (clamped knots, The
            // NURBS Book eq. 3.8 / 3.17); the constant c does not change "lies in the plane".
            double residual = 0.0;
            const int row = static_cast<int>(rhs.size());
            for (int c = 0; c <= p; ++c) {
                const int i = span - p + c;
                const size_t inner = gridIndex(g.side, i, 1, nu, nv);
                residual += N[c] * n.dot(pts[inner] - pts[gridIndex(g.side, i, 0, nu, nv)]);
                if (slot[inner] >= 0)
                    for (int d = 0; d < 3; ++d) entries.emplace_back(row, 3 * slot[inner] + d, N[c] * n[d]);
            }
            rhs.push_back(-residual);
        }
    }
    Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(rhs.size()), 3 * unknowns);
    A.setFromTriplets(entries.begin(), entries.end());
    const Eigen::Map<const Eigen::VectorXd> b(rhs.data(), static_cast<Eigen::Index>(rhs.size()));
    Eigen::SparseMatrix<double> AtA = A.transpose() * A;
    double scale = 0.0;
    for (Eigen::Index k = 0; k < AtA.rows(); ++k) scale = std::max(scale, AtA.coeff(k, k));
    for (Eigen::Index k = 0; k < AtA.rows(); ++k) AtA.coeffRef(k, k) += kRegularization * std::max(scale, 1.0);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(AtA);
    if (ldlt.info() != Eigen::Success) throw GeometryError("tangents: the G1 conditions could not be solved");
    const Eigen::VectorXd delta = ldlt.solve(A.transpose() * b);
    for (size_t q = 0; q < pts.size(); ++q)
        if (slot[q] >= 0) pts[q] += delta.segment<3>(3 * slot[q]);
}

double maxG1AngleDegrees(const Surface3d& surface, const std::vector<G1Side>& sides)
{
    // A surface normal from derivatives whose cross product is below this fraction of their
    // lengths is direction noise (a collapsed side, or tangent boundaries at a lens corner).
    constexpr double kDegenerateSine = 1e-8;
    double worst = 0.0;
    for (const G1Side& g : sides)
        for (size_t k = 0; k < g.samples.size(); ++k) {
            const Vec3& n = g.normals[k];
            if (n.squaredNorm() < 0.5) continue;
            const Eigen::Vector2d uv = patchParams(g.side, g.samples[k]);
            const auto d = surface.derivatives(uv.x(), uv.y(), 1);
            const Vec3 N = d[1][0].cross(d[0][1]);
            const double scale = d[1][0].norm() * d[0][1].norm();
            if (!(N.norm() > kDegenerateSine * scale)) continue;
            const double c = std::min(1.0, std::abs(N.normalized().dot(n)));
            worst = std::max(worst, std::acos(c) * 180.0 / kPi);
        }
    return worst;
}

}  // namespace sculptline::solvers::surfaces
