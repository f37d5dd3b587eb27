#include "solvers/surfaces/rotation_minimizing_frames.h"

#include "solvers/bspline/geometry_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

namespace sculptline::solvers::surfaces {

namespace {

// Dense samples per knot span for the cusp test.
constexpr int kCuspSamplesPerSpan = 64;
// A speed below this fraction of the mean speed (length / parameter range) is a vanishing derivative.
constexpr double kMinRelativeSpeed = 1e-8;

}  // namespace

Eigen::Matrix3d Frame::axes() const
{
    Eigen::Matrix3d m;
    m << tangent, normal, binormal;
    return m;
}

Eigen::Vector3d unitTangent(const Curve3d& path, double u)
{
    const Eigen::Vector3d d = path.derivatives(u, 1)[1];
    return d.normalized();
}

Frame propagateFrame(const Frame& f, const Eigen::Vector3d& x1, const Eigen::Vector3d& t1)
{
    const Eigen::Vector3d v1 = x1 - f.origin;
    const double c1 = v1.squaredNorm();
    Eigen::Vector3d rL = f.normal;
    Eigen::Vector3d tL = f.tangent;
    if (c1 > 0.0) {
        rL = f.normal - (2.0 / c1) * v1.dot(f.normal) * v1;
        tL = f.tangent - (2.0 / c1) * v1.dot(f.tangent) * v1;
    }
    const Eigen::Vector3d v2 = t1 - tL;
    const double c2 = v2.squaredNorm();
    Eigen::Vector3d r1 = c2 > 0.0 ? Eigen::Vector3d(rL - (2.0 / c2) * v2.dot(rL) * v2) : rL;
    // Re-orthonormalize against round-off drift over many steps.
    r1 = (r1 - r1.dot(t1) * t1).normalized();
    return Frame{x1, t1, r1, t1.cross(r1)};
}

std::vector<Frame> rotationMinimizingFrames(const Curve3d& path, const std::vector<double>& params,
                                            const Eigen::Vector3d& initialNormal)
{
    return rotationMinimizingFrames(CurveJet3d(path), params, initialNormal);
}

std::vector<Frame> rotationMinimizingFrames(const CurveJet3d& path, const std::vector<double>& params,
                                            const Eigen::Vector3d& initialNormal)
{
    std::vector<Frame> frames;
    frames.reserve(params.size());
    if (params.empty()) return frames;
    Eigen::Vector3d x, d1, d2;
    path.evaluate(params.front(), x, d1, d2);
    const Eigen::Vector3d t0 = d1.normalized();
    Eigen::Vector3d r0 = initialNormal - initialNormal.dot(t0) * t0;
    r0 = r0.norm() > 1e-12 * initialNormal.norm() ? Eigen::Vector3d(r0.normalized()) : t0.unitOrthogonal();
    frames.push_back(Frame{x, t0, r0, t0.cross(r0)});
    for (size_t k = 1; k < params.size(); ++k) {
        path.evaluate(params[k], x, d1, d2);
        frames.push_back(propagateFrame(frames.back(), x, d1.normalized()));
    }
    return frames;
}

void requireNoCusp(const Curve3d& path)
{
    const double a = path.domainStart();
    const double b = path.domainEnd();
    std::vector<double> breaks{a};
    for (double k : interiorBreakpoints(path.degree(), path.knots())) breaks.push_back(k);
    breaks.push_back(b);
    const CurveJet3d jet(path);
    double length = 0.0;
    Eigen::Vector3d prev = path.evaluate(a);
    std::vector<double> params;
    std::vector<Eigen::Vector3d> derivatives;
    for (size_t s = 0; s + 1 < breaks.size(); ++s)
        for (int k = (s == 0 ? 0 : 1); k <= kCuspSamplesPerSpan; ++k) {
            const double u = breaks[s] + (breaks[s + 1] - breaks[s]) * k / kCuspSamplesPerSpan;
            Eigen::Vector3d p, d1, d2;
            jet.evaluate(u, p, d1, d2);
            params.push_back(u);
            derivatives.push_back(d1);
            length += (p - prev).norm();
            prev = p;
        }
    if (!(length > 0.0)) throw GeometryError("path: zero length, nothing to sweep along");
    const double meanSpeed = length / (b - a);
    Eigen::Vector3d lastTangent = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < params.size(); ++k) {
        const double u = params[k];
        const Eigen::Vector3d& d = derivatives[k];
        if (!(d.norm() > kMinRelativeSpeed * meanSpeed))
            throw GeometryError("path: cusp at u = " + std::to_string(u) +
                                " (the tangent vanishes); a profile cannot be swept through it");
        const Eigen::Vector3d t = d.normalized();
        if (lastTangent.norm() > 0.0 && std::acos(std::clamp(t.dot(lastTangent), -1.0, 1.0)) > kCuspTurn)
            throw GeometryError("path: cusp near u = " + std::to_string(u) +
                                " (the tangent turns back); a profile cannot be swept through it");
        lastTangent = t;
    }
}

}  // namespace sculptline::solvers::surfaces
