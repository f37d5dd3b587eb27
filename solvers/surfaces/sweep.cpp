#include "solvers/surfaces/sweep.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/interpolation.h"
#include "solvers/surfaces/rotation_minimizing_frames.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <memory>

namespace sculptline::solvers::surfaces {

namespace {

// Profile samples per control point when measuring the deviation between sections.
constexpr int kProfileSamplesPerPoint = 2;
// Cross-direction degree: cubic interpolation of the sections (C2 across, like the strokes).
constexpr int kCrossDegree = 3;
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
    const ControlMatrix rows = profile.homogeneous();

    // Reference normal: the profile's principal direction off the tangent would do as well; the
    // swept shape does not depend on it (an RMF rotated about t0 rotates every frame alike).
    const Eigen::Vector3d n0 = unitTangent(path, a).unitOrthogonal();
    const Eigen::Vector3d x0 = path.evaluate(a);

    std::vector<double> uSamples;
    const int us = kProfileSamplesPerPoint * n;
    for (int i = 0; i <= us; ++i) uSamples.push_back(profile.domainStart() + (profile.domainEnd() - profile.domainStart()) * i / us);
    std::vector<Eigen::Vector3d> profilePts;
    for (double u : uSamples) profilePts.push_back(profile.evaluate(u) - x0);

    const int spans = static_cast<int>(interiorBreakpoints(path.degree(), path.knots()).size()) + 1;
    int count = std::min(std::max(kCrossDegree + 1, 2 * spans + 1), std::max(kCrossDegree + 1, options.maxSections));
    std::unique_ptr<SweepResult> best;
    for (;;) {
        // Frames at kProbes·(count - 1) + 1 parameters: every kProbes-th is a section, the others
        // (quarter points between sections) measure the deviation; one frame sweep serves both.
        std::vector<double> params;
        for (int k = 0; k <= kProbes * (count - 1); ++k) params.push_back(a + (b - a) * k / (kProbes * (count - 1.0)));
        const std::vector<Frame> frames = rotationMinimizingFrames(path, params, n0);
        const Eigen::Matrix3d base = frames.front().axes().transpose();
        ControlMatrix data(count, static_cast<Eigen::Index>(n) * h);
        std::vector<double> v(count);
        for (int k = 0; k < count; ++k) {
            const Frame& f = frames[kProbes * k];
            const Eigen::Matrix3d M = f.axes() * base;
            v[k] = static_cast<double>(k) / (count - 1);
            for (int i = 0; i < n; ++i) {
                const double w = profile.weight(i);
                const Eigen::Vector3d p = f.origin + M * (profile.points()[i] - x0);
                data.block(k, static_cast<Eigen::Index>(i) * h, 1, 3) = w * p.transpose();
                if (h == 4) data(k, static_cast<Eigen::Index>(i) * h + 3) = w;
            }
        }
        const CurveInterpolator interp(v, std::min(kCrossDegree, count - 1));
        const ControlMatrix net = interp.solve(data);
        Surface3d s = Surface3d::fromGroupedRows(Direction::V, profile.degree(), interp.degree(), profile.knots(),
                                                 interp.knots(), net, profile.isRational());
        double deviation = 0.0;
        for (int k = 0; k + 1 < count; ++k)
            for (int q = 1; q < kProbes; ++q) {
                const Frame& f = frames[kProbes * k + q];
                const Eigen::Matrix3d M = f.axes() * base;
                const double vm = (k + static_cast<double>(q) / kProbes) / (count - 1);
                for (size_t i = 0; i < uSamples.size(); ++i)
                    deviation = std::max(deviation, (s.evaluate(uSamples[i], vm) - (f.origin + M * profilePts[i])).norm());
            }
        best = std::make_unique<SweepResult>(SweepResult{std::move(s), deviation, count, tolerance});
        if (deviation <= tolerance || 2 * count - 1 > options.maxSections) break;
        count = 2 * count - 1;  // keeps the old sections (their parameters) and adds the midpoints
    }
    return *best;
}

}  // namespace sculptline::solvers::surfaces
