#pragma once
// Recognition measured on real pen strokes: the $1 unistroke gesture logs (Wobbrock, Wilson and Li,
// UIST 2007; tests/data/unistrokes/README.md) run through the pipeline the window uses
// (fitStroke, then recognizeShape, both with default options; the fit without its minimax trials,
// classFitOptions).
#include "solvers/stroke/shape_recognizer.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace sculptline::stroketest {

using solvers::stroke::ShapeKind;

/// One logged gesture: pixel coordinates (y up) and seconds since the first sample.
struct Recording {
    std::string subject;  ///< "s02".."s11"
    std::string gesture;  ///< "triangle", "left_curly_brace", ...
    std::string speed;    ///< "slow", "medium", "fast"
    int number = 0;       ///< 1..10, the order in which the subject drew it at that speed
    solvers::stroke::Stroke stroke;
};

/// The fit options of every recognition here: the defaults without the minimax trials
/// (FitOptions::minimaxTrials). They change the fitted curve's control points, never what the class
/// is read from (the conditioned stroke, its corners and whether the curve is closed: strokeGeometry
/// in shape_recognizer.cpp), and they are most of the fit's time on these strokes, which the
/// sanitizer build pays on every test that recognizes the 2,400 development strokes.
/// UnistrokeRecognition.GivenDevelopmentStrokes_WhenFittedWithOrWithoutMinimaxTrials_ThenTheSameClass
/// holds the two to the same class.
solvers::stroke::FitOptions classFitOptions();

/// All recordings of the given subjects ("s02".."s11") from `dir` (one CSV per subject).
/// @throws std::runtime_error when a file is missing or malformed.
std::vector<Recording> loadUnistrokes(const std::string& dir, const std::vector<std::string>& subjects);

/// The development subjects (tuning allowed) and the held-out ones (report only). The public logs
/// have no s01, so development is s02-s06.
std::vector<std::string> devSubjects();
std::vector<std::string> heldOutSubjects();
/// The Quick, Draw! drawings made in one stroke (tests/data/quickdraw/README.md): circle, square,
/// triangle, line, star, zigzag, hexagon, octagon; `subject` is "quickdraw", `speed` the player's
/// country code. A second source of real strokes, from other people and devices, used only to test.
std::vector<Recording> loadQuickDraw(const std::string& dir = SCULPTLINE_QUICKDRAW_DATA);

/// The classes a designer reads each gesture as: triangle -> triangle; rectangle -> rectangle or
/// square; circle -> circle or ellipse; straight-segment marks (check, caret, v, square brackets,
/// star, arrow, x, delete mark) -> polyline; curved marks (pigtail, question mark, curly braces)
/// -> freeform. The first entry is the class the gesture is reported under.
const std::vector<ShapeKind>& acceptedKinds(const std::string& gesture);
bool isCorrect(const std::string& gesture, ShapeKind kind);

constexpr int kKinds = 10;   ///< ShapeKind values
constexpr int kFailed = 10;  ///< column of strokes the fitter rejected

/// Counts per gesture of each recognized kind (columns: ShapeKind, then kFailed).
struct Confusion {
    std::map<std::string, std::array<int, kKinds + 1>> rows;
    int total() const;
    int correct() const;
    double accuracy() const;
    double accuracy(const std::string& gesture) const;
    /// Accuracy over all gestures whose reported class is `kind`.
    double classAccuracy(ShapeKind kind) const;
    /// Markdown: per-gesture rows, recognized kinds as columns, accuracy per row.
    std::string table() const;
};

/// The recognized kind of one recording, or -1 when fitting failed.
int recognizeRecording(const Recording& r, const solvers::stroke::RecognizeOptions& options = {});

Confusion evaluate(const std::vector<Recording>& recordings, const solvers::stroke::RecognizeOptions& options = {});

}  // namespace sculptline::stroketest

namespace sculptline::stroketest {

/// Adapting to a person (UserModel::learnShape): per subject, the strokes numbered <= `firstN` at
/// each gesture and speed teach the model (the designer confirms each stroke read as one of its
/// gesture's classes and corrects any other to the gesture's first class); the rest are recognized
/// with and without the learned habits.
struct AdaptationResult {
    std::string subject;
    int trained = 0, tested = 0;
    int correctBefore = 0, correctAfter = 0;
};
std::vector<AdaptationResult> adaptPerSubject(const std::vector<Recording>& recordings, int firstN,
                                              const solvers::stroke::RecognizeOptions& options = {});

}  // namespace sculptline::stroketest

namespace sculptline::stroketest {

/// The stroke as a window of another size would pass it: points scaled by `scale` about the origin,
/// then resampled by linear interpolation (of position and time) at `spacing` times the stroke's
/// mean sample spacing, along its polyline, first and last samples kept. spacing = 1 keeps the
/// samples as they are. This is what a window of another size does to a stroke: it passes plane
/// units (mm), and the pen's samples, events a pixel or more apart, come denser or sparser in mm.
solvers::stroke::Stroke transformStroke(const solvers::stroke::Stroke& stroke, double scale, double spacing);

/// How often a transformed stroke gets the class of the original.
struct InvarianceResult {
    double scale = 1, spacing = 1;
    int total = 0, same = 0;
    int correctOriginal = 0, correctTransformed = 0;
    std::map<std::string, int> changedByGesture;
    std::map<std::string, int> transitions;  ///< "circle->ellipse": count
};
InvarianceResult measureInvariance(const std::vector<Recording>& recordings, double scale, double spacing,
                                   const solvers::stroke::RecognizeOptions& options = {});

}  // namespace sculptline::stroketest

namespace sculptline::stroketest {

/// A development stress test of how a person might draw the same gesture otherwise (a perturbation
/// of a real stroke, not a synthetic one): rotated about its centroid by `rotateDeg`, stretched along
/// the plane's x axis by `aspect` (before the rotation: a rectangle stays a rectangle), its last `cutShare` of arc length left off
/// (a loop the hand did not close), its start reached again and its first `overshootShare` of arc
/// length drawn again (a loop overshot along its first side; the repeated samples are spaced and
/// timed as the originals), or drawn on straight past its end by `extendShare` of its length (the
/// closing corner overshot), and its times scaled by `timeScale` (a slower or faster hand).
/// Also: each point moved to the mean of the path within `roundShare` of the stroke's length around
/// it (a box filter along the arc: corners rounded off with a radius of about a quarter of that, as
/// a hand drawing fast does), and only every `keepEvery`-th sample kept (ends kept: a coarser pen).
struct Perturbation {
    double rotateDeg = 0, aspect = 1, cutShare = 0, overshootShare = 0, timeScale = 1, extendShare = 0;
    double roundShare = 0;
    int keepEvery = 1;
    /// Drawn from a little before its start: a straight lead-in of this share of its length, on the
    /// line of its first 5 % (with extendShare: a loop begun and ended past the same corner).
    double leadInShare = 0;
    /// Drawn sheared: x moved by this times the height above the centroid (a parallelogram; 0.3 leans
    /// the sides by 17 degrees).
    double shear = 0;
    /// Drawn in perspective, tapered: x scaled about the centroid by 1 - taper * (y - centroid) / height,
    /// so a rectangle's top edge is about 1 - taper/2 and its bottom edge 1 + taper/2 of its width (a
    /// trapezoid).
    double taper = 0;
    /// Drawn with a wavering hand: each sample moved along the stroke's normal by `wobble` times the
    /// extent (the larger side of its bounding box) times sin(2 pi wobbleWaves s / L), s its arc length.
    double wobble = 0;
    double wobbleWaves = 5;
};
solvers::stroke::Stroke perturbStroke(const solvers::stroke::Stroke& stroke, const Perturbation& p);

}  // namespace sculptline::stroketest
