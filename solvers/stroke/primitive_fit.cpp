#include "solvers/stroke/primitive_fit.h"

#include "solvers/math_constants.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::solvers::stroke {
namespace {


Point2 centroid(const std::vector<Point2>& pts)
{
    Point2 c = Point2::Zero();
    for (const auto& p : pts) c += p;
    return c / static_cast<double>(pts.size());
}

double segmentDistance(const Point2& p, const Point2& a, const Point2& b)
{
    const Point2 ab = b - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

}  // namespace

LineFit fitLine(const std::vector<Point2>& pts)
{
    LineFit f;
    f.point = centroid(pts);
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const auto& p : pts) cov += (p - f.point) * (p - f.point).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
    f.direction = eig.eigenvectors().col(1);  // largest eigenvalue
    const Point2 normal(-f.direction.y(), f.direction.x());
    for (const auto& p : pts) f.maxResidual = std::max(f.maxResidual, std::abs((p - f.point).dot(normal)));
    return f;
}

CircleFit fitCircle(const std::vector<Point2>& pts)
{
    CircleFit f;
    if (pts.size() < 3) return f;
    // Kasa: minimize sum (x^2 + y^2 + D x + E y + F)^2, linear in D, E, F; centred for conditioning.
    const Point2 c0 = centroid(pts);
    Eigen::MatrixXd A(pts.size(), 3);
    Eigen::VectorXd b(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        const Point2 q = pts[i] - c0;
        A.row(i) << q.x(), q.y(), 1.0;
        b(i) = -q.squaredNorm();
    }
    const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
    Point2 c(-0.5 * s(0), -0.5 * s(1));
    double r2 = c.squaredNorm() - s(2);
    if (!(r2 > 0) || !std::isfinite(r2)) return f;
    double r = std::sqrt(r2);
    // Gauss-Newton on sum (|q - c| - r)^2.
    for (int it = 0; it < 20; ++it) {
        Eigen::MatrixXd J(pts.size(), 3);
        Eigen::VectorXd res(pts.size());
        for (size_t i = 0; i < pts.size(); ++i) {
            const Point2 d = pts[i] - c0 - c;
            const double n = std::max(d.norm(), 1e-300);
            res(i) = n - r;
            J.row(i) << -d.x() / n, -d.y() / n, -1.0;
        }
        const Eigen::Vector3d step = J.colPivHouseholderQr().solve(-res);
        c += step.head<2>();
        r += step(2);
        if (step.norm() < 1e-12 * (1 + r)) break;
    }
    if (!(r > 0) || !std::isfinite(r)) return f;
    f.center = c + c0;
    f.radius = r;
    for (const auto& p : pts) f.maxResidual = std::max(f.maxResidual, std::abs((p - f.center).norm() - r));
    f.valid = true;
    return f;
}

EllipseFit fitEllipse(const std::vector<Point2>& pts)
{
    EllipseFit f;
    if (pts.size() < 6) return f;
    const Point2 c0 = centroid(pts);
    double scale = 0;
    for (const auto& p : pts) scale = std::max(scale, (p - c0).norm());
    if (!(scale > 0)) return f;
    // Halir & Flusser: D1 = [x^2 xy y^2], D2 = [x y 1]; S1 a1 + S2 a2 ... with the constraint
    // 4ac - b^2 = 1 as the 3x3 eigenproblem M a1 = lambda a1, M = C1^-1 (S1 - S2 S3^-1 S2^T).
    Eigen::MatrixXd D1(pts.size(), 3), D2(pts.size(), 3);
    for (size_t i = 0; i < pts.size(); ++i) {
        const Point2 q = (pts[i] - c0) / scale;
        D1.row(i) << q.x() * q.x(), q.x() * q.y(), q.y() * q.y();
        D2.row(i) << q.x(), q.y(), 1.0;
    }
    const Eigen::Matrix3d S1 = D1.transpose() * D1, S2 = D1.transpose() * D2, S3 = D2.transpose() * D2;
    const Eigen::FullPivLU<Eigen::Matrix3d> s3(S3);
    if (!s3.isInvertible()) return f;
    const Eigen::Matrix3d T = -s3.inverse() * S2.transpose();
    const Eigen::Matrix3d M0 = S1 + S2 * T;
    Eigen::Matrix3d M;
    M.row(0) = M0.row(2) / 2.0;
    M.row(1) = -M0.row(1);
    M.row(2) = M0.row(0) / 2.0;
    Eigen::EigenSolver<Eigen::Matrix3d> eig(M);
    int pick = -1;
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d v = eig.eigenvectors().col(k).real();
        if (4 * v(0) * v(2) - v(1) * v(1) > 0) pick = k;
    }
    if (pick < 0) return f;
    const Eigen::Vector3d a1 = eig.eigenvectors().col(pick).real();
    const Eigen::Vector3d a2 = T * a1;
    const double A = a1(0), B = a1(1), C = a1(2), D = a2(0), E = a2(1), F = a2(2);
    // Centre, axes and angle of A x^2 + B xy + C y^2 + D x + E y + F = 0.
    const double den = B * B - 4 * A * C;
    if (!(std::abs(den) > 0)) return f;
    const Point2 c((2 * C * D - B * E) / den, (2 * A * E - B * D) / den);
    const double num = 2 * (A * E * E + C * D * D - B * D * E + den * F);
    const double root = std::sqrt((A - C) * (A - C) + B * B);
    const double q1 = -std::sqrt(std::max(0.0, num * (A + C + root))) / den;
    const double q2 = -std::sqrt(std::max(0.0, num * (A + C - root))) / den;
    if (!(q1 > 0) || !(q2 > 0) || !std::isfinite(q1) || !std::isfinite(q2)) return f;
    double theta = (B != 0) ? std::atan2(C - A - root, B) : (A < C ? 0.0 : kPi / 2);
    f.center = c0 + scale * c;
    f.a = scale * std::max(q1, q2);
    f.b = scale * std::min(q1, q2);
    f.angle = q1 >= q2 ? theta : theta + kPi / 2;
    // Residual against a 720-gon of the ellipse (chord sagitta < 1e-4 a): each point is measured
    // against the 16 edges around its eccentric-anomaly guess atan2(y / b, x / a), which brackets
    // the foot point for ellipses up to ~10:1 (the guess errs by less than 16 edges = 8 degrees
    // near the flat sides there), instead of all 720.
    constexpr int kEdges = 720, kWindow = 8;
    const Point2 ua(std::cos(f.angle), std::sin(f.angle)), ub(-ua.y(), ua.x());
    auto at = [&](int i) {
        const double t = 2 * kPi * i / kEdges;
        return Point2(f.center + f.a * std::cos(t) * ua + f.b * std::sin(t) * ub);
    };
    for (const auto& p : pts) {
        const Point2 q = p - f.center;
        const double t0 = std::atan2(q.dot(ub) / f.b, q.dot(ua) / f.a);
        const int i0 = static_cast<int>(std::floor(t0 / (2 * kPi) * kEdges));
        double best = std::numeric_limits<double>::infinity();
        for (int i = i0 - kWindow; i <= i0 + kWindow; ++i) best = std::min(best, segmentDistance(p, at(i), at(i + 1)));
        f.maxResidual = std::max(f.maxResidual, best);
    }
    f.valid = true;
    return f;
}

double polylineResidual(const std::vector<Point2>& pts, const std::vector<Point2>& v, bool closed)
{
    double worst = 0;
    const size_t edges = closed ? v.size() : v.size() - 1;
    for (const auto& p : pts) {
        double best = std::numeric_limits<double>::infinity();
        for (size_t e = 0; e < edges; ++e) best = std::min(best, segmentDistance(p, v[e], v[(e + 1) % v.size()]));
        worst = std::max(worst, best);
    }
    return worst;
}

}  // namespace sculptline::solvers::stroke
