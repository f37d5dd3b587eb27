#include "solvers/surfaces/sweep.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/rotation_minimizing_frames.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <memory>

namespace sculptline::solvers::surfaces {

namespace {

// Profile samples per control point when measuring the deviation between sections.
constexpr int kProfileSamplesPerPoint = 2;
// Sections per path knot span to start from (then doubled until the tolerance is met).
constexpr int kInitialPerSpan = 2;
// Probes per interval between sections: the interpolation error peaks inside each interval, not
// necessarily at its middle; quarter points bound it to within a few percent.
constexpr int kProbes = 4;

}  // namespace

SweepResult sweep(const Curve3d& input, const Curve3d& inputPath, const SweepOptions& options)
{
    const Curve3d profile = input.clamped();
    const Curve3d path = inputPath.clamped();
    requireNoCusp(path);
    const double size = std::max(profile.controlSize(), path.controlSize());
    const double tolerance = options.tolerance > 0.0 ? options.tolerance : kDefaultSweepRelative * size;
    const double a = path.domainStart();
    const double b = path.domainEnd();
    const int n = profile.pointCount();
    const int h = profile.isRational() ? 4 : 3;

    // Reference normal: the profile's principal direction off the tangent would do as well; the
    // swept shape does not depend on it (an RMF rotated about t0 rotates every frame alike).
    const Eigen::Vector3d n0 = unitTangent(path, a).unitOrthogonal();
    const Eigen::Vector3d x0 = path.evaluate(a);

    std::vector<double> uSamples;
    const int us = kProfileSamplesPerPoint * n;
    for (int i = 0; i <= us; ++i) uSamples.push_back(profile.domainStart() + (profile.domainEnd() - profile.domainStart()) * i / us);
    std::vector<Eigen::Vector3d> profilePts;
    for (double u : uSamples) profilePts.push_back(profile.evaluate(u) - x0);
    // u basis at the samples, fixed for every probe (The NURBS Book A2.1, A2.2).
    const int pu = profile.degree();
    std::vector<int> uSpan;
    std::vector<std::vector<double>> uBasis;
    for (double u : uSamples) {
        uSpan.push_back(findSpan(pu, profile.knots(), u));
        uBasis.emplace_back(pu + 1);
        basisFunctions(uSpan.back(), u, pu, profile.knots(), uBasis.back().data());
    }

    // Sections at m equally spaced parameters per path knot span (so every path knot, where the
    // exact sweep is only C1, is a section), joined by cubic Hermite pieces with the exact
    // derivative of the moving section: C1 in v, error O(h^4) on each piece (de Boor, "A Practical
    // Guide to Splines", ch. IV) instead of the O(h^2) a C2 interpolant gets across the C1 knots.
    std::vector<double> breaks{a};
    for (double k : interiorBreakpoints(path.degree(), path.knots())) breaks.push_back(k);
    breaks.push_back(b);
    const int spans = static_cast<int>(breaks.size()) - 1;
    int perSpan = std::max(1, std::min(kInitialPerSpan, (options.maxSections - 1) / spans));
    std::unique_ptr<SweepResult> best;
    for (;;) {
        const int count = spans * perSpan + 1;
        // Frames at kProbes points per interval: every kProbes-th is a section, the others (quarter
        // points between sections) measure the deviation; one frame sweep serves both.
        std::vector<double> params;
        for (int s0 = 0; s0 < spans; ++s0)
            for (int k = 0; k < kProbes * perSpan; ++k)
                params.push_back(breaks[s0] + (breaks[s0 + 1] - breaks[s0]) * k / (kProbes * perSpan));
        params.push_back(b);
        const std::vector<Frame> frames = rotationMinimizingFrames(path, params, n0);
        const Eigen::Matrix3d base = frames.front().axes().transpose();
        // Control rows of the C1 cubic (double knots at the inner sections): S_k, then S_k ± h/3·S'_k.
        ControlMatrix net(2 * count, static_cast<Eigen::Index>(n) * h);
        KnotVector knotsV(4, 0.0);
        std::vector<double> v(count);
        for (int k = 0; k < count; ++k) v[k] = (params[kProbes * k] - a) / (b - a);
        v.back() = 1.0;
        for (int k = 1; k + 1 < count; ++k) knotsV.insert(knotsV.end(), 2, v[k]);
        knotsV.insert(knotsV.end(), 4, 1.0);
        for (int k = 0; k < count; ++k) {
            const double t = params[kProbes * k];
            const Frame& f = frames[kProbes * k];
            const Eigen::Matrix3d M = f.axes() * base;
            // d/dt of x(t) + M(t)(P - x0): x'(t) + ω × M(P - x0), ω = T × dT/dt, the angular
            // velocity of a rotation-minimizing frame (no component along T; Bishop 1975).
            const auto d = path.derivatives(t, 2);
            const double speed = d[1].norm();
            const Eigen::Vector3d T = d[1] / speed;
            const Eigen::Vector3d dT = (d[2] - d[2].dot(T) * T) / speed;
            const Eigen::Vector3d omega = T.cross(dT);
            const double hPrev = k > 0 ? v[k] - v[k - 1] : 0.0;
            const double hNext = k + 1 < count ? v[k + 1] - v[k] : 0.0;
            for (int i = 0; i < n; ++i) {
                const double w = profile.weight(i);
                const Eigen::Vector3d rel = M * (profile.points()[i] - x0);
                const Eigen::Vector3d p = f.origin + rel;
                const Eigen::Vector3d dp = (b - a) * (d[1] + omega.cross(rel));  // d/dv
                const auto put = [&](int row, const Eigen::Vector3d& x) {
                    net.block(row, static_cast<Eigen::Index>(i) * h, 1, 3) = w * x.transpose();
                    if (h == 4) net(row, static_cast<Eigen::Index>(i) * h + 3) = w;
                };
                // Row layout: S_0, S_0 + h0/3 S'_0, S_1 - h0/3 S'_1, S_1 + h1/3 S'_1, ..., S_last.
                if (k == 0) {
                    put(0, p);
                    put(1, p + hNext / 3.0 * dp);
                } else if (k + 1 == count) {
                    put(2 * k, p - hPrev / 3.0 * dp);
                    put(2 * k + 1, p);
                } else {
                    put(2 * k, p - hPrev / 3.0 * dp);
                    put(2 * k + 1, p + hNext / 3.0 * dp);
                }
            }
        }
        Surface3d s = Surface3d::fromGroupedRows(Direction::V, profile.degree(), 3, profile.knots(), knotsV, net,
                                                 profile.isRational());
        double deviation = 0.0;
        for (int k = 0; k + 1 < count; ++k)
            for (int q = 1; q < kProbes; ++q) {
                const Frame& f = frames[kProbes * k + q];
                const Eigen::Matrix3d M = f.axes() * base;
                const double vm = (params[kProbes * k + q] - a) / (b - a);
                // The probe's iso-curve rows (v basis applied to the net), then the fixed u samples.
                const int vSpan = findSpan(3, knotsV, vm);
                double nv[4];
                basisFunctions(vSpan, vm, 3, knotsV, nv);
                Eigen::RowVectorXd iso = Eigen::RowVectorXd::Zero(net.cols());
                for (int r = 0; r < 4; ++r) iso += nv[r] * net.row(vSpan - 3 + r);
                for (size_t i = 0; i < uSamples.size(); ++i) {
                    Eigen::Vector4d hp = Eigen::Vector4d::Zero();
                    for (int c = 0; c <= pu; ++c) {
                        const Eigen::Index col = static_cast<Eigen::Index>(uSpan[i] - pu + c) * h;
                        hp.head<3>() += uBasis[i][c] * iso.segment(col, 3).transpose();
                        hp(3) += uBasis[i][c] * (h == 4 ? iso(col + 3) : 1.0);
                    }
                    const Eigen::Vector3d x = hp.head<3>() / hp(3);
                    deviation = std::max(deviation, (x - (f.origin + M * profilePts[i])).norm());
                }
            }
        best = std::make_unique<SweepResult>(SweepResult{std::move(s), deviation, count, tolerance});
        if (deviation <= tolerance || spans * 2 * perSpan + 1 > options.maxSections) break;
        perSpan *= 2;  // keeps the old sections (their parameters) and adds the midpoints
    }
    return *best;
}

}  // namespace sculptline::solvers::surfaces
