#pragma once
// Single-stroke shape recognition and regularization (thesis §3.1.1, Fig. 3-3, Table 3-1 STEP 2:
// G(L, S, P, V) -> T_i(C_j)).
#include "solvers/stroke/primitive_fit.h"
#include "solvers/stroke/stroke_fitter.h"

#include <string>

namespace sculptline::solvers::stroke {

/// The classes of thesis Fig. 3-3. All are invariant under rotation of the stroke in its plane except
/// one pair, by definition: Square and Diamond differ only in orientation relative to the drawing
/// plane's axes (StrokeGeometry::axisU/axisV; the x and y axes for a planar stroke). A square whose
/// sides run within 22.5 degrees of the axes is a Square; the same square standing on a corner is a
/// Diamond. A rhombus that is not right-angled is a Diamond at any orientation. So square/diamond
/// answers are invariant under rotations by multiples of 90 degrees only (shape_recognition_test,
/// GivenRotatedStrokes_WhenRecognized_ThenSameClassExceptSquareDiamondOffQuarterTurns).
enum class ShapeKind { Line, Arc, Circle, Ellipse, Triangle, Rectangle, Square, Diamond, Polyline, Freeform };

/// "line", "arc", ... as in ../shared/interfaces.md (`recognize`).
const char* shapeName(ShapeKind kind);

struct ShapeCandidate {
    ShapeKind kind = ShapeKind::Freeform;
    double score = 0;  ///< in [0, 1], higher is better
};

/// The 4-tuple of thesis Table 3-1: length L, speed S, point set P, vertex set V (in the stroke's
/// plane), plus the plane and whether the stroke closes.
struct StrokeGeometry {
    double length = 0;               ///< L
    double speed = 0;                ///< S, average (model units per second, or per sample)
    std::vector<Point2> points;      ///< P, conditioned points in plane coordinates
    std::vector<Point2> vertices;    ///< V, ends (open) and corners, in order
    std::vector<int> vertexIndex;    ///< index of each vertex in `points`
    bool closed = false;
    double extent = 0;
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< plane frame: x = origin + u * axisU + v * axisV
    Eigen::Vector3d axisU = Eigen::Vector3d::UnitX(), axisV = Eigen::Vector3d::UnitY();
};

/// Builds G from a fit: a planar stroke keeps its xy (or its best-fit plane, for 3D strokes).
StrokeGeometry strokeGeometry(const FitResult& fit);

struct RecognizeOptions {
    /// The recognizer resamples the stroke at this arc-length spacing (share of the extent) and
    /// finds its corners again there: the pen's sample density depends on the device and, in plane
    /// units, on the window's size (pixels per mm), and the corner detector's minimum neighbourhood
    /// (FeatureOptions::k samples) and every maximum residual over the samples with it. 0 = use the
    /// fit's own samples and corners.
    double sampleSpacing = 0.02;
    /// Residual scale, relative to the stroke's extent, at which a primitive's score falls to
    /// 1/e: 10 %. Measured on real pen strokes (the $1 unistroke logs, development subjects, see
    /// tests/data/unistrokes): the largest deviation of hand-drawn triangles, rectangles, checks and
    /// circles from their ideal shape is 3-6 % of the extent at the median and about 10 % at the
    /// 95th percentile (seed 003 §4 assumed a few per cent, from synthesized strokes).
    double residualScale = 0.10;
    /// Score of the freeform interpretation, the fallback when nothing fits better.
    double freeformScore = 0.35;
    /// Sides within this relative difference count as equal (square, diamond).
    double equalSides = 0.2;
    /// Angles within this of 90 degrees count as right (radians; 15 degrees).
    double rightAngle = 0.26;
    /// Polygon vertices are refined for recognition: the point farthest from the polygon becomes
    /// a vertex while it lies farther than this share of residualScale (a corner the detector
    /// missed, often at a loop's seam), and vertices turning less than `collinearAngle` are
    /// dropped (a corner detected on a straight side).
    double vertexInsertion = 0.3;
    /// ... but only where the stroke turns by at least this angle there (radians, 60 degrees): a
    /// corner. The farthest point of a smoothly curved piece turns less (a circle seen from the
    /// vertices of its inscribed square: 45 degrees), so curves are not chopped into chords.
    double minCornerTurn = 1.05;
    /// ... read from the edge's ends and, where that turns less, from the samples this share of the
    /// extent along the stroke either side of the point, or the edge's ends where nearer (0: from
    /// the edge's ends only). A rounded corner turns more over its own legs than seen from a far
    /// edge end (a square bracket's: 55 degrees from the ends, 66 over the legs). Chosen by
    /// leave-one-subject-out on the development subjects' perturbed copies (unistroke-report
    /// --augment --loso cornerLeg 0,0.1,0.16,0.2,0.25,0.3: 0.2 on all five folds, pooled 97.6 %
    /// against 97.0 % off; --augment-drawn likewise, 96.0 against 95.5 %).
    double cornerLeg = 0.2;
    /// ... or, on a loop read as three vertices, where the edge is two straight sides meeting at
    /// the point: every sample of either half within this share of the insertion distance
    /// (vertexInsertion) of the half's chord, both halves longer than twice shortEdge, the turn at
    /// least 45 degrees (refineVertices). A hand's skewed or tapered rectangle turns 55-60 degrees
    /// at its obtuse corners, below minCornerTurn, and was then read as a triangle that fits
    /// nothing (freeform) or an ellipse. Chosen by leave-one-subject-out on the development
    /// subjects and their perturbed copies (unistroke-report --augment --augment-rounded
    /// --augment-drawn --augment-sloppy --loso straightLegs 0,0.5,0.75,1,1.5,2): 1 on all five
    /// folds, pooled 40,345 of 43,200 against 40,317 without the rule. 0 turns the rule off.
    double straightLegs = 1.0;
    /// Polygon scores are multiplied by this for each vertex inserted beyond those expected (the
    /// detected corners, and on a loop the seam and one more): a polygon that needs many guessed
    /// vertices is a curve approximated by chords.
    double guessedVertex = 0.5;
    double collinearAngle = 0.44;  ///< radians, 25 degrees
    /// Polygon sides are fitted as lines to the middle of each edge, leaving out this share of the
    /// edge's samples at either end (rounded and overshot corners); see edgeLineVertices. Chosen
    /// by leave-one-subject-out on the development strokes (unistroke-report --loso edgeTrim
    /// 0,0.05,0.1,0.15,0.2,0.3): 0.05 on four of the five folds, 0.1 on the fifth; pooled 97.2 %
    /// against 96.9 % at the former 0.2.
    double edgeTrim = 0.05;
    /// A loop's guessed vertices (not at a detected corner) on a triangle or quadrilateral are
    /// moved to the samples nearest where its sides meet, the sides being lines fitted to the
    /// middle of each edge (relocateTrim of its samples left out at either end), for up to
    /// relocateRounds rounds (relocateVertices), where the sides meet within relocateShift of the
    /// extent from the vertex; 0 rounds leave them where refineVertices put them. A vertex placed
    /// on a rounded corner as the farthest sample from a diagonal lies toward the longer side, and
    /// the polygon came out skewed: development rectangles with corners rounded over 12 % of the
    /// length and drawn on 10 % past the start were read as ellipses 54 times in 150
    /// (`unistroke-report --dump-dev rectangle` with DUMP_PERTURB=0,1,0,0.1,1,0,0.12), 9 with the
    /// rule. Chosen by leave-one-subject-out on the development subjects and their perturbed copies
    /// (unistroke-report --augment --augment-rounded --augment-drawn --augment-sloppy --loso),
    /// pooled of 43,200, 40,345 without the rule:
    /// - first with the polygon's edgeTrim (0.05): relocateRounds 0,1,2,3,5 chose 1 on all five
    ///   folds (40,377), relocateShift 0.08,0.15,0.25,0.4 0.25 on four (40,377);
    /// - then relocateTrim 0.05,0.1,0.15,0.2,0.25,0.35 chose 0.35 on all five (40,386), and
    ///   0.25,...,0.45 0.35 on four and 0.4 on one;
    /// - with it relocateRounds 0,1,2,3 chose 3 on four folds (40,389), and with 3 rounds
    ///   relocateTrim 0.05,0.25,0.3,0.35,0.4 0.35 on four (40,391) and relocateShift 0.15,0.25,0.4
    ///   0.25 on four (40,393 at these defaults).
    int relocateRounds = 3;
    double relocateShift = 0.25;
    double relocateTrim = 0.35;
    /// A rectangle or square also scores by how closely the stroke follows it with its corners
    /// rounded, by a radius of up to this share of its shorter half-side (the best of 0, 0.05, ...):
    /// a hand drawing fast rounds the corners off, and the straight sides are what makes it a
    /// rectangle rather than an ellipse (an ellipse misses a rounded rectangle's sides, a rectangle
    /// rounded by half its half-side misses a circle by a fifth of its radius). The rectangle is
    /// still regularized with sharp corners. 0 = sharp corners only.
    double cornerRounding = 0.5;
    /// A closed stroke read as a convex quadrilateral that is no rectangle by its angles (skewed,
    /// sheared, drawn in perspective) is also offered as a rectangle, scored by how closely the
    /// stroke follows its own four-vertex polygon (the polygon's score, residualScale as for every
    /// polygon) times this factor; the rectangle candidate's score is the better of that and the
    /// regular rectangle's. The quad must be convex, every interior angle at least 60 degrees, at
    /// least three of its four vertices corners the detector found (not vertices the refinement
    /// inserted), and its sides not all equal (QuadShape::equal: squares and diamonds are
    /// unaffected). So the loose reading counts only where the regular rectangle fits worse than the
    /// quad's own score times this factor; above 0.5 it beats the quad's polyline reading (scored at
    /// 0.5 of the polygon), but not a round shape or freeform that fits better. A rectangle
    /// recognized this way is still regularized as the regular rectangle (regularRectangle). A
    /// hand's rectangle drawn fast or at an angle to the hand is often a parallelogram or a
    /// trapezoid whose angles stray by more than rightAngle from 90 degrees; without this rule they
    /// fall to polyline or freeform. 0 turns the rule off. Chosen by leave-one-subject-out on the
    /// development subjects and their perturbed copies, sheared and tapered copies among them
    /// (unistroke-report --set looseQuad=0 --augment-drawn --loso looseQuad 0,0.4,0.5,0.6,0.7,0.8):
    /// 0.6 on all five folds, pooled 95.4 % against 94.6 % without the rule (26,400 strokes). 0.6,
    /// 0.7 and 0.8 score the same on every fold (0.9 and 1.0 the same pooled) and the tool keeps the
    /// first, the most cautious: at 0.6 the loose reading beats freeform only where the quad misses
    /// the stroke by less than 0.73 of the residual scale. At 0.5 it recognizes 5 strokes fewer, at
    /// 0.4 the same as 0. On the strokes as drawn: 97.7 -> 97.8 %, rectangles 98.0 -> 99.3 %, no
    /// other gesture changes.
    double looseQuad = 0.6;
    /// A loop whose quad, with its corners rounded (cornerRounding's radii, the quad's own angles:
    /// sheared and tapered too), lies closer to the stroke than this share of the circle's or the
    /// ellipse's residual has straight sides: that round shape counts it against itself as it
    /// counts detected corners (halved), and the quad may be read as a loose rectangle (looseQuad)
    /// without three detected corners. A hand drawing a rectangle fast rounds every corner beyond
    /// the corner detector's sharpness test, and a skewed or tapered one was then read as an
    /// ellipse. The rounded quad has 9 parameters against the ellipse's 5, so a share below 1 would
    /// ask for more than closer; chosen by leave-one-subject-out on the development subjects and
    /// their perturbed copies, among them copies drawn two ways at once (unistroke-report
    /// --augment-rounded --augment-drawn --augment-sloppy --loso roundedSides 0,0.6,0.7,0.8,0.9,1:
    /// 1 on four folds and 0.9 on the fifth; pooled 40,316 of 43,200 against 40,282 without the
    /// rule, 0.8 gives 40,314). 0 turns the rule off.
    double roundedSides = 1.0;
    double shortEdge = 0.08;       ///< edges shorter than this share of the extent are merged
    /// recognizeStroke: a loop that the conditioning closed by trimming more than this share of its
    /// length as overshoot was a stroke crossing itself (an x, a delete mark), not a loop that
    /// closed: it is fitted again as an open stroke. A hand closing a loop overshoots by a few per
    /// cent of its perimeter.
    double maxOvershoot = 0.25;
    /// recognizeStroke: ... and so was a loop whose start and end both go on past the place where the
    /// conditioning closed it, each farther than this share of the extent from the loop (an x, a
    /// delete mark, an alpha: the stroke crosses itself with both ends sticking out). A hand closing
    /// a loop starts on it and only its end overshoots, along the loop or a short way past its
    /// first corner, so the rule also asks that the stroke meets its own path at the seam at more
    /// than 45 degrees (an overshoot along the loop arrives the way it left). 0 turns the rule off.
    /// Chosen by leave-one-subject-out on the development subjects and their perturbed copies
    /// (unistroke-report --augment --loso crossingTail 0,0.05,0.1,0.15,0.2: 0.05 on all five folds,
    /// pooled 96.7 % against 96.5 % without the rule); on the strokes as drawn alone it changes two
    /// of 2,400 (a delete mark gained, a circle whose ends cross lost).
    double crossingTail = 0.05;
    /// recognizeStroke: an open stroke that turns around its centre by at least this angle (and by
    /// less than `maxLoopTurn`: not a spiral or a pigtail) is a loop whose ends the hand did not quite
    /// bring together; it is fitted again as a closed stroke (radians: 300 and 380 degrees).
    double minLoopTurn = 5.24;
    double maxLoopTurn = 6.63;
    /// recognizeStroke: ... and so is an open stroke that turns by at least `nearLoopTurn` (and
    /// less than maxLoopTurn) whose end heads for its start: the closing segment, end to start, is
    /// within `nearLoopHeading` of the stroke's direction over its last tenth of the extent, and no
    /// longer than `nearLoopGap` of the stroke's length. A hand that stops short of closing a
    /// figure stops on the last side, still drawing towards the start; the open strokes that turn
    /// as far (a question mark's hook, a spiral's inner end) end heading elsewhere. 0 turns it off.
    /// Radians (258 and 50 degrees), chosen by leave-one-subject-out on the development subjects
    /// and their perturbed copies (unistroke-report --augment --loso nearLoopTurn / nearLoopHeading
    /// / nearLoopGap): development loops left open by 10 % of their length, rectangles 77 -> 98 %,
    /// triangles 81 -> 99 %, circles 68 -> 95 %; the strokes as drawn are unchanged.
    double nearLoopTurn = 4.5;
    double nearLoopHeading = 0.87;
    double nearLoopGap = 0.3;
    /// UserModel::applyHabits: a stroke within this mean distance (share of the extent) of a shape
    /// the user corrected before is read as that correction.
    double habitDistance = 0.1;
    /// Replace the stroke by the exact primitive (false: `regularized` is the fitted curve).
    bool regularize = true;
};

struct Recognition {
    ShapeKind kind = ShapeKind::Freeform;
    std::vector<ShapeCandidate> candidates;  ///< ranked, best first
    /// The regularized primitive (exact rational circle/arc/ellipse of degree 2, polygons and lines
    /// of degree 1), or the fitted cubic for freeform shapes / when regularization is declined.
    /// Circles, ellipses, triangles, squares, rectangles, diamonds and closed polylines are closed
    /// (periodic) curves: isClosed() is true and their JSON form carries "closed": true.
    Curve3d regularized{1, {0.0, 0.0, 1.0, 1.0}, {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()}};
    StrokeGeometry geometry;
    // Primitive parameters of the best candidate (plane coordinates), for composite reasoning.
    LineFit line;
    CircleFit circle;
    EllipseFit ellipse;
    std::vector<Point2> polygon;  ///< regularized vertices of polygon kinds
};

/// Classifies one fitted stroke and regularizes it.
Recognition recognizeShape(const FitResult& fit, const RecognizeOptions& options = {});

/// A raw stroke fitted (fitStroke) and recognized (recognizeShape), as the window does when the pen
/// lifts; a loop closed by trimming a long overshoot is refitted open (RecognizeOptions::maxOvershoot),
/// an open stroke that nearly closes is refitted closed (minLoopTurn, nearLoopTurn). Closing is a
/// guess that must explain the stroke: where the closed fit reads as freeform and the open one as
/// a shape, the open reading stays (an arrow whose head's last line runs back toward the shaft's
/// start turns far enough and heads for its start, but closed it is no shape).
struct StrokeRecognition {
    FitResult fit;
    Recognition recognition;
};
/// @throws GeometryError as fitStroke.
StrokeRecognition recognizeStroke(const Stroke& stroke, const FitOptions& fitOptions = {}, const RecognizeOptions& options = {});

/// The stroke regularized as another of its candidates (the designer picks the second-best, say):
/// `recognition` is recognizeShape(fit)'s result. Freeform gives the fitted curve.
/// @throws std::invalid_argument when `kind` is not among recognition.candidates.
Curve3d regularizeAs(const Recognition& recognition, const FitResult& fit, ShapeKind kind);

/// An exact circular arc as a rational quadratic B-spline (The NURBS Book A7.1): centre, radius
/// and angles in the plane frame of `g`; a full turn gives the 9-point circle as a closed (periodic)
/// curve: 8 distinct points, the first two repeated (isClosed() true).
Curve3d makeArc(const StrokeGeometry& g, const Point2& center, double radius, double a0, double a1);

}  // namespace sculptline::solvers::stroke
