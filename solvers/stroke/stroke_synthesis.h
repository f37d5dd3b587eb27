#pragma once
// Strokes synthesized from known curves with human-like timing and digitizer noise: the ground truth
// of the stroke tests, benchmarks and the splprep comparison (scripts/compare_splprep.py). Timing
// follows the two-thirds power law of hand movement (Lacquaniti, Terzuolo & Viviani 1983: speed ~
// curvature^(-1/3)), with a further slow-down approaching corners (the pen nearly stops at a
// vertex), sampled at a fixed digitizer rate.
#include "solvers/stroke/stroke.h"

#include <functional>
#include <random>

namespace sculptline::solvers::stroke {


/// A test shape (planar unless made by helixShape or from 3D vertices): a dense polyline of the exact curve (the reference), and which vertices are
/// intended corners.
struct Shape {
    std::vector<Eigen::Vector3d> reference;  ///< dense, exact
    std::vector<int> corners;     ///< indices into reference
    /// Smooth bends where the hand nearly stops without meaning a corner (indices into reference);
    /// drawn with the same slow-down as corners.
    std::vector<int> slowdowns;
    bool closed = false;
};

Shape lineShape(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
Shape arcShape(const Eigen::Vector3d& center, double radius, double a0, double a1);
Shape circleShape(const Eigen::Vector3d& center, double radius, double startAngle = 0.3);
Shape ellipseShape(const Eigen::Vector3d& center, double a, double b, double rotation);
/// A loop with one corner: (r cos t, r sin t sin(t/2)), t in [0, 2 pi), its tip at (r, 0) turning
/// by 90 degrees (both sides leave it at 45 degrees to the axis), the corner at reference index 0.
Shape teardropShape(double r);
Shape polygonShape(const std::vector<Eigen::Vector3d>& vertices, bool closed);
Shape sCurveShape(double size);
Shape spiralShape(double size, double turns);
/// A free-hand flourish: a wave of two superposed frequencies, several tight bends where the hand
/// slows down (the kind of stroke of thesis Fig. 4-3).
Shape flourishShape(double size);

/// The stroke of thesis Fig. 4-3 as far as the figure shows it: a long free-hand curve whose
/// gently bowed sweeps (fast) are joined by tight rounded turns where the pen nearly stops
/// (`legs` sweeps `size` long, hairpins of radius `turnRadius`, each a `slowdowns` entry). Smooth
/// everywhere (C2 is kept in the figure): the turns are slow bends, not corners.
Shape hairpinShape(double size, int legs, double turnRadius);

/// A space curve: `turns` turns of a helix of `radius` about the z axis, rising `pitch` per turn,
/// starting at (radius, 0, 0). Non-planar for turns > 0 and pitch != 0.
Shape helixShape(double radius, double pitch, double turns);

struct DrawOptions {
    double rate = 120.0;        ///< digitizer samples per second
    double peakSpeed = 400.0;   ///< model units per second on straight parts
    double noise = 0.0;         ///< standard deviation of positional noise, model units
    double cornerSlowdown = 0.12; ///< speed factor at a corner (1 = no slow-down)
    unsigned seed = 1;
    bool withTimes = true;
    /// Closed shapes: the pen stops this fraction of the perimeter past its start (negative: short
    /// of it), as hand-drawn loops overshoot or leave a gap.
    double closureOffset = 0.0;
};

/// Draws the shape as a hand would: arc-length speed profile, fixed-rate samples, Gaussian noise
/// (in x and y for a shape in the plane z = 0, which gives a 2D stroke; in x, y and z for any
/// other shape, which gives a 3D stroke).
Stroke draw(const Shape& shape, const DrawOptions& options = {});

/// Draws `shape` with about `samples` samples (the digitizer rate is scaled to reach the count).
Stroke drawWithSamples(const Shape& shape, int samples, DrawOptions options = {});

/// Max distance from points to the reference polyline (point-to-segment, brute force).
double distanceToPolyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& poly, bool closed);

}  // namespace sculptline::solvers::stroke
