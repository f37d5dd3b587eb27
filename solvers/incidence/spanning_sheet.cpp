#include "solvers/incidence/spanning_sheet.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/coons_fill.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace sculptline::solvers::incidence {
namespace {

/// How far (relative to the rim's size) the sheet's boundary may stray from the rim before the
/// construction is refused: the Coons patch interpolates its sides exactly, so only round-off
/// (1e-15 relative) and the fill's corner snapping of ends that meet to round-off remain.
constexpr double kRimTolerance = 1e-9;

/// The second principal extent below which the points count as one line, relative to the first: a
/// line sampled to round-off (1e-16 relative) is far below it, a visibly bent curve far above.
constexpr double kCollinearRatio = 1e-9;

}  // namespace

Surface3d spanningSheet(const std::vector<Eigen::Vector3d>& points, int count, double margin)
{
    if (count < 4) throw GeometryError("count: a bicubic sheet needs at least 4 control points per direction, got " + std::to_string(count));
    if (!(margin >= 0.0 && std::isfinite(margin))) throw GeometryError("margin: must be finite and not negative");
    if (points.size() < 3) throw GeometryError("points: the curves span no surface (fewer than three points)");
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points) {
        if (!p.allFinite()) throw GeometryError("points: not finite");
        centroid += p;
    }
    centroid /= static_cast<double>(points.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& p : points) scatter += (p - centroid) * (p - centroid).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);  // ascending eigenvalues
    const Eigen::Vector3d spread = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    if (!(spread(2) > 0.0) || spread(1) <= kCollinearRatio * spread(2))
        throw GeometryError("points: the curves lie on one line and span no surface");
    const Eigen::Vector3d e1 = eigen.eigenvectors().col(2).normalized();
    const Eigen::Vector3d e2 = eigen.eigenvectors().col(0).cross(e1).normalized();  // right-handed with the normal
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Eigen::Vector3d& p : points) {
        const Eigen::Vector2d q((p - centroid).dot(e1), (p - centroid).dot(e2));
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    const double grow = margin * (hi - lo).maxCoeff();
    lo -= Eigen::Vector2d::Constant(grow);
    hi += Eigen::Vector2d::Constant(grow);
    constexpr int degree = 3;
    KnotVector knots(static_cast<size_t>(count + degree + 1));
    const int spans = count - degree;
    for (int i = 0; i < static_cast<int>(knots.size()); ++i) {
        knots[static_cast<size_t>(i)] = std::clamp(static_cast<double>(i - degree) / spans, 0.0, 1.0);
    }
    std::vector<double> greville(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        double sum = 0.0;
        for (int k = 1; k <= degree; ++k) sum += knots[static_cast<size_t>(i + k)];
        greville[static_cast<size_t>(i)] = sum / degree;
    }
    std::vector<Eigen::Vector3d> net;
    net.reserve(static_cast<size_t>(count * count));
    for (int i = 0; i < count; ++i) {
        for (int j = 0; j < count; ++j) {
            const double x = lo.x() + greville[static_cast<size_t>(i)] * (hi.x() - lo.x());
            const double y = lo.y() + greville[static_cast<size_t>(j)] * (hi.y() - lo.y());
            net.push_back(centroid + x * e1 + y * e2);
        }
    }
    return Surface3d(degree, degree, knots, knots, count, count, net);
}

Surface3d refinedForIncidence(const Surface3d& surface, int count)
{
    Surface3d sheet = surface;
    for (Direction d : {Direction::U, Direction::V}) {
        const double s0 = sheet.domainStart(d), s1 = sheet.domainEnd(d);
        const int missing = count - sheet.count(d);
        if (missing <= 0) continue;
        std::vector<double> x;
        for (int i = 1; i <= missing; ++i) {
            const double t = s0 + (s1 - s0) * i / (missing + 1);
            // Not on a present knot (refinement inserts each once).
            if (std::find(sheet.knots(d).begin(), sheet.knots(d).end(), t) == sheet.knots(d).end()) x.push_back(t);
        }
        if (!x.empty()) sheet = sheet.refine(d, x);
    }
    return sheet;
}

BoundedSheet sheetBoundedBy(const Curve3d& rim, int count)
{
    if (!rim.isClosed()) throw GeometryError("rim: must be a closed curve");
    if (rim.isRational()) throw GeometryError("rim: must not be rational");
    if (count < 4) throw GeometryError("count: a bicubic sheet needs at least 4 control points per direction, got " + std::to_string(count));
    const double a = rim.domainStart(), b = rim.domainEnd(), q = (b - a) / 4.0;
    std::vector<Curve3d> sides;
    for (int k = 0; k < 4; ++k) sides.push_back(rim.extract(a + k * q, a + (k + 1) * q));
    // The fill runs side 2 and side 3 backwards (v = 1 and u = 0 from the far corner): the loop's
    // own orientation is kept by the fill's chaining.
    Surface3d sheet = surfaces::fill(sides);
    sheet = refinedForIncidence(sheet, count);
    const double u0 = sheet.domainStart(Direction::U), u1 = sheet.domainEnd(Direction::U);
    const double v0 = sheet.domainStart(Direction::V), v1 = sheet.domainEnd(Direction::V);
    // Degree 1, closed: corners (u0, v0), (u1, v0), (u1, v1), (u0, v1) at a, a + q, a + 2q, a + 3q;
    // the unwrapped convention: one point repeated, knots a − q .. b + q.
    const std::vector<Eigen::Vector2d> corners{{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}, {u0, v0}};
    KnotVector knots;
    for (int k = -1; k <= 5; ++k) knots.push_back(a + k * q);
    Curve2d domain(1, knots, corners, {}, true);
    // The fill may have chained the sides in the other orientation: then the corners run the other
    // way round. Whichever reproduces the rim is its pre-image.
    const double size = [&] {
        Eigen::Vector3d lo = rim.points().front(), hi = lo;
        for (const Eigen::Vector3d& p : rim.points()) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        return std::max((hi - lo).maxCoeff(), 1e-300);
    }();
    auto gap = [&](const Curve2d& g) {
        double worst = 0.0;
        for (int k = 0; k <= 256; ++k) {
            const double t = a + (b - a) * k / 256.0;
            const Eigen::Vector2d uv = g.evaluate(t);
            worst = std::max(worst, (sheet.evaluate(uv.x(), uv.y()) - rim.evaluate(t)).norm());
        }
        return worst;
    };
    if (gap(domain) > kRimTolerance * size) {
        const std::vector<Eigen::Vector2d> other{{u0, v0}, {u0, v1}, {u1, v1}, {u1, v0}, {u0, v0}};
        Curve2d reversed(1, knots, other, {}, true);
        const double g = gap(reversed);
        if (g > kRimTolerance * size)
            throw GeometryError("rim: its quarters do not bound a sheet (the boundary strays " + std::to_string(g) + " from it)");
        domain = reversed;
    }
    return {sheet, domain};
}

}  // namespace sculptline::solvers::incidence
