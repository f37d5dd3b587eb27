// unistroke-report: recognition accuracy on the $1 unistroke logs (tests/data/unistrokes), as
// Markdown confusion matrices for the development subjects (s02-s06) and, with --held-out, for the
// held-out subjects (s07-s11).
//   unistroke-report [--dev] [--held-out] [--quickdraw] [--data DIR] [--set option=value]...
//                                              (--quickdraw: the Quick, Draw! drawings made in one
//                                              stroke, tests/data/quickdraw; a test set only)
//   unistroke-report --adapt dev|held-out      accuracy per person before/after learning corrections
//   unistroke-report --dump-dev GESTURE        one line per development recording of GESTURE
//   unistroke-report --loso OPTION V1,V2,..    leave-one-subject-out on s02-s06 for one option
//   unistroke-report --augment --loso ...      the same on s02-s06 and their perturbed copies
//   unistroke-report --augment-rounded --loso ...  ... and copies with corners rounded (8 %, 12 %)
//   unistroke-report --augment-drawn --loso ...  ... and copies drawn sheared (0.3, 0.5) and tapered
//                                              (0.4, 0.7), as a hand draws a rectangle askew
//   unistroke-report --augment-sloppy --loso ...  ... and copies rounded (8 %) and sheared (0.3),
//                                              tapered (0.4), overshot (10 %) or left open (6 %), and
//                                              rounded 16 %: a fast, careless hand
//   unistroke-report --fit-dev                 the fit alone on the development strokes: control
//                                              points, loops and time per gesture (FIT_NAMES=1: and
//                                              one line per stroke; strays: strokes whose curve
//                                              strays from the stroke, FitResult::stray;
//                                              --no-stray-bound before it: FitOptions::boundStray off;
//                                              --no-pieces-searched: FitOptions::piecesSearched off)
//   unistroke-report --features-dev            TSV of what the recognizer measured, for tuning
//   unistroke-report --invariance dev|held-out  the same strokes scaled (x0.1, x10) and resampled
//                                              (0.5x, 2x the sample spacing): how often the class holds
//   unistroke-report --perturb-dev             the development strokes rotated, stretched, left open,
//                                              overshot and sped up (Perturbation): accuracy per gesture
// --set changes a RecognizeOptions field (residualScale, freeformScore, vertexInsertion,
// collinearAngle, shortEdge, minCornerTurn, guessedVertex, maxOvershoot, minLoopTurn, habitDistance,
// crossingTail, cornerLeg, nearLoopTurn, nearLoopHeading, nearLoopGap, cornerRounding, edgeTrim, sampleSpacing,
// looseQuad, roundedSides, straightLegs, relocateRounds, relocateShift, relocateTrim).
// Options are read left to right: put --set before the mode (--perturb-dev, --loso, ...).
// The dump, feature, perturbation and leave-one-out modes read the development subjects only: the
// held-out ones are not for tuning.
#include "unistroke_eval.h"

#include "solvers/stroke/stroke_fitter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace st = sculptline::stroketest;

namespace {

sculptline::solvers::stroke::RecognizeOptions gOptions;
bool gAugment = false;
bool gAugmentRounded = false;
bool gAugmentDrawn = false;
bool gAugmentSloppy = false;

// Strokes drawn two ways at once, as a fast, careless hand does: corners rounded over 8 % of the
// length and sheared 0.3, tapered 0.4, overshot 10 % or left 6 % open; and rounded over 16 %
// (--augment-sloppy, and rows of --perturb-dev).
const std::vector<std::pair<const char*, st::Perturbation>>& sloppyWays()
{
    static const std::vector<std::pair<const char*, st::Perturbation>> ways = {
        {"corners rounded 16 %", {0, 1, 0, 0, 1, 0, 0.16}},
        {"rounded 8 %, sheared 0.3", {0, 1, 0, 0, 1, 0, 0.08, 1, 0, 0.3, 0}},
        {"rounded 8 %, tapered 0.4", {0, 1, 0, 0, 1, 0, 0.08, 1, 0, 0, 0.4}},
        {"rounded 8 %, overshoot 10 %", {0, 1, 0, 0.1, 1, 0, 0.08}},
        {"rounded 8 %, end cut 6 %", {0, 1, 0.06, 0, 1, 0, 0.08}},
    };
    return ways;
}

// The development recordings and, for each, the same stroke drawn otherwise as a person might
// (perturbStroke): rotated 30 degrees, stretched 0.7 and 1.5 along x, its end left 3 % and 6 % short
// of closing, drawn on 3 % past its end. Each copy keeps its subject, so that leave-one-subject-out
// on them still leaves whole people out (--augment --loso).
std::vector<st::Recording> augmented(const std::vector<st::Recording>& recs)
{
    const std::vector<st::Perturbation> ways = {
        {30, 1, 0, 0, 1, 0}, {0, 0.7, 0, 0, 1, 0}, {0, 1.5, 0, 0, 1, 0}, {0, 1, 0.03, 0, 1, 0}, {0, 1, 0.06, 0, 1, 0}, {0, 1, 0, 0, 1, 0.03},
    };
    std::vector<st::Recording> out = recs;
    std::vector<st::Perturbation> all = ways;
    if (gAugmentRounded) {  // --augment-rounded: also with corners rounded over 8 % and 12 % of the length
        all.push_back({0, 1, 0, 0, 1, 0, 0.08});
        all.push_back({0, 1, 0, 0, 1, 0, 0.12});
    }
    if (gAugmentDrawn) {  // --augment-drawn: also sheared 0.3 and 0.5, tapered 0.4 and 0.7 (Perturbation)
        for (double shear : {0.3, 0.5}) {
            st::Perturbation p;
            p.shear = shear;
            all.push_back(p);
        }
        for (double taper : {0.4, 0.7}) {
            st::Perturbation p;
            p.taper = taper;
            all.push_back(p);
        }
    }
    if (gAugmentSloppy)  // --augment-sloppy: also drawn two ways at once (sloppyWays)
        for (const auto& [name, p] : sloppyWays()) all.push_back(p);
    for (const auto& p : all)
        for (const auto& r : recs) {
            out.push_back(r);
            out.back().stroke = st::perturbStroke(r.stroke, p);
        }
    return out;
}

void report(const char* title, const std::vector<st::Recording>& recs)
{
    const st::Confusion c = st::evaluate(recs, gOptions);
    std::cout << "### " << title << "\n\n" << c.table() << "\nPer class: ";
    for (auto k : {st::ShapeKind::Line, st::ShapeKind::Triangle, st::ShapeKind::Rectangle, st::ShapeKind::Circle,
                   st::ShapeKind::Polyline, st::ShapeKind::Freeform}) {
        // (Only the classes some gesture of the set maps to: the $1 logs have no line.)
        bool present = false;
        for (const auto& [gesture, row] : c.rows) present = present || st::acceptedKinds(gesture).front() == k;
        if (!present) continue;
        std::cout << sculptline::solvers::stroke::shapeName(k) << ' ' << std::fixed << std::setprecision(1) << 100.0 * c.classAccuracy(k) << " %  ";
    }
    std::cout << "\n\n";
}

// Sets the RecognizeOptions field called `k`; false for an unknown name.
bool setOption(sculptline::solvers::stroke::RecognizeOptions& o, const std::string& k, double v)
{
    if (k == "residualScale") o.residualScale = v;
    else if (k == "sampleSpacing") o.sampleSpacing = v;
    else if (k == "edgeTrim") o.edgeTrim = v;
    else if (k == "freeformScore") o.freeformScore = v;
    else if (k == "vertexInsertion") o.vertexInsertion = v;
    else if (k == "collinearAngle") o.collinearAngle = v;
    else if (k == "shortEdge") o.shortEdge = v;
    else if (k == "minCornerTurn") o.minCornerTurn = v;
    else if (k == "cornerLeg") o.cornerLeg = v;
    else if (k == "guessedVertex") o.guessedVertex = v;
    else if (k == "habitDistance") o.habitDistance = v;
    else if (k == "maxOvershoot") o.maxOvershoot = v;
    else if (k == "minLoopTurn") o.minLoopTurn = v;
    else if (k == "crossingTail") o.crossingTail = v;
    else if (k == "nearLoopTurn") o.nearLoopTurn = v;
    else if (k == "cornerRounding") o.cornerRounding = v;
    else if (k == "nearLoopHeading") o.nearLoopHeading = v;
    else if (k == "nearLoopGap") o.nearLoopGap = v;
    else if (k == "looseQuad") o.looseQuad = v;
    else if (k == "straightLegs")
        o.straightLegs = v;
    else if (k == "roundedSides")
        o.roundedSides = v;
    else if (k == "relocateRounds")
        o.relocateRounds = static_cast<int>(v);
    else if (k == "relocateShift")
        o.relocateShift = v;
    else if (k == "relocateTrim")
        o.relocateTrim = v;
    else return false;
    return true;
}

// Leave-one-subject-out on the development subjects: for each of s02-s06, the value of option `k`
// (among `values`) that recognizes the other four best is chosen, and the left-out subject is
// recognized with it. The pooled accuracy estimates how well choosing that parameter on some people
// carries over to another person (held-out subjects are not read).
void leaveOneSubjectOut(const std::vector<st::Recording>& recs, const std::string& k, const std::vector<double>& values)
{
    std::map<std::string, std::map<double, std::pair<int, int>>> perSubject;  // subject -> value -> (correct, total)
    for (double v : values) {
        sculptline::solvers::stroke::RecognizeOptions o = gOptions;
        setOption(o, k, v);
        for (const auto& r : recs) {
            const int kind = st::recognizeRecording(r, o);
            auto& c = perSubject[r.subject][v];
            c.first += kind >= 0 && st::isCorrect(r.gesture, static_cast<st::ShapeKind>(kind));
            ++c.second;
        }
    }
    std::cout << "| left out | " << k << " chosen on the other four | their accuracy | left-out accuracy | left-out at the default |\n|---|---:|---:|---:|---:|\n";
    int correct = 0, total = 0, correctDefault = 0;
    sculptline::solvers::stroke::RecognizeOptions defaults = gOptions;
    for (const auto& [out, unused] : perSubject) {
        double bestV = values.front(), bestAcc = -1;
        for (double v : values) {
            int c = 0, t = 0;
            for (const auto& [s, byV] : perSubject) {
                if (s == out) continue;
                c += byV.at(v).first;
                t += byV.at(v).second;
            }
            if (double(c) / t > bestAcc + 1e-12) {
                bestAcc = double(c) / t;
                bestV = v;
            }
        }
        const auto& mine = perSubject[out][bestV];
        int dc = 0;
        for (const auto& r : recs) {
            if (r.subject != out) continue;
            const int kind = st::recognizeRecording(r, defaults);
            dc += kind >= 0 && st::isCorrect(r.gesture, static_cast<st::ShapeKind>(kind));
        }
        correct += mine.first;
        total += mine.second;
        correctDefault += dc;
        std::cout << "| " << out << " | " << std::defaultfloat << std::setprecision(6) << bestV << " | " << std::fixed << std::setprecision(1) << 100.0 * bestAcc << " % | "
                  << 100.0 * mine.first / mine.second << " % | " << 100.0 * dc / mine.second << " % |" << std::defaultfloat << '\n';
    }
    std::cout << "| **pooled** | | | " << std::fixed << std::setprecision(1) << 100.0 * correct / total << " % (" << correct << '/' << total << ") | "
              << 100.0 * correctDefault / total << " % (" << correctDefault << '/' << total << ") |" << std::defaultfloat << '\n';
}

double turnDeg(const std::vector<sculptline::solvers::stroke::Point2>& pts, const sculptline::solvers::stroke::Point2& c)
{
    double total = 0, prev = std::atan2(pts.front().y() - c.y(), pts.front().x() - c.x());
    for (const auto& p : pts) {
        const double a = std::atan2(p.y() - c.y(), p.x() - c.x());
        double d = a - prev;
        if (d > M_PI) d -= 2 * M_PI;
        if (d < -M_PI) d += 2 * M_PI;
        total += d;
        prev = a;
    }
    return std::abs(total) * 180 / M_PI;
}

// One line per recording of `gesture`: what the recognizer saw (for development on s02-s06 only).
void dump(const std::vector<st::Recording>& recs, const std::string& gesture)
{
    namespace sk = sculptline::solvers::stroke;
    for (const auto& r : recs) {
        if (r.gesture != gesture) continue;
        sk::RecognizeOptions o = gOptions;
        o.regularize = false;
        // DUMP_SPACING=f: the stroke resampled at f times its sample spacing (--invariance).
        const double spacing = std::getenv("DUMP_SPACING") ? std::atof(std::getenv("DUMP_SPACING")) : 1.0;
        // DUMP_PERTURB=rotateDeg,aspect,cutShare,overshootShare,timeScale,extendShare,roundShare,keepEvery,
        // leadInShare,shear,taper,wobble,wobbleWaves (--perturb-dev).
        st::Perturbation pert;
        if (const char* e = std::getenv("DUMP_PERTURB")) {
            std::sscanf(e, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%d,%lf,%lf,%lf,%lf,%lf", &pert.rotateDeg, &pert.aspect,
                        &pert.cutShare, &pert.overshootShare, &pert.timeScale, &pert.extendShare, &pert.roundShare,
                        &pert.keepEvery, &pert.leadInShare, &pert.shear, &pert.taper, &pert.wobble, &pert.wobbleWaves);
        }
        const sk::Stroke given = st::perturbStroke(st::transformStroke(r.stroke, 1.0, spacing), pert);
        const sk::StrokeRecognition sr = sk::recognizeStroke(given, {}, o);
        const sk::FitResult& fit = sr.fit;
        const sk::Recognition& rec = sr.recognition;
        std::cout << r.subject << ' ' << r.speed << ' ' << r.number << " n=" << r.stroke.points.size() << " cond=" << fit.conditioned.size()
                  << " closed=" << rec.geometry.closed << " corners=" << fit.corners.size() << " verts=" << rec.geometry.vertices.size()
                  << " ext=" << std::setprecision(3) << rec.geometry.extent << " len=" << rec.geometry.length << " ->";
        for (const auto& c : rec.candidates) std::cout << ' ' << sk::shapeName(c.kind) << ':' << std::setprecision(2) << c.score;
        std::cout << (st::isCorrect(r.gesture, rec.kind) ? "" : "  WRONG");
        if (std::getenv("DUMP_LOOP") && rec.circle.valid) {  // turn about the fitted circle's centre, end gap / extent
            const auto& q = rec.geometry.points;
            std::cout << "  turn=" << std::setprecision(3) << turnDeg(q, rec.circle.center) << " gap=" << (q.back() - q.front()).norm() / rec.geometry.extent;
            // How far the closing segment (end -> start) is from the stroke's heading at its end and
            // at its start (degrees), headings over a tenth of the extent.
            const auto heading = [&](bool atEnd) {
                const int n = static_cast<int>(q.size());
                const int a = atEnd ? n - 1 : 0, step = atEnd ? -1 : 1;
                int j = a;
                while (j + step >= 0 && j + step < n && (q[j] - q[a]).norm() < 0.1 * rec.geometry.extent) j += step;
                return sk::Point2(atEnd ? q[a] - q[j] : q[j] - q[a]);
            };
            const sk::Point2 gapDir = q.front() - q.back();
            const auto angle = [](const sk::Point2& u, const sk::Point2& v) {
                return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)) * 180 / M_PI;
            };
            std::cout << " hend=" << angle(heading(true), gapDir) << " hstart=" << angle(heading(false), gapDir)
                      << " gaplen=" << gapDir.norm() / rec.geometry.length;
        }
        if (std::getenv("DUMP_VERTICES")) {  // vertices in units of the extent, from the points' first sample
            std::cout << "  V:";
            for (const auto& v : rec.geometry.vertices) {
                const auto q = (v - rec.geometry.points.front()) / rec.geometry.extent;
                std::cout << " (" << std::setprecision(2) << q.x() << ',' << q.y() << ')';
            }
        }
        if (std::getenv("DUMP_VERTICES")) {  // and the samples the polygon's vertices were found at, of how many
            std::cout << "  I:";
            for (int k : rec.geometry.vertexIndex) std::cout << ' ' << k;
            std::cout << " of " << rec.geometry.points.size();
        }
        if (std::getenv("DUMP_RAW")) {  // the stroke given to the recognizer (perturbed): x,y,t (y up, s)
            std::cout << "  R:";
            for (size_t k = 0; k < given.points.size(); ++k)
                std::cout << std::setprecision(6) << ' ' << given.points[k].x() << ',' << given.points[k].y() << ','
                          << (k < given.times.size() ? given.times[k] : 0.0);
        }
        if (std::getenv("DUMP_POINTS")) {  // the recognizer's (resampled) points, plane coordinates
            std::cout << "  P:";
            for (const auto& p : rec.geometry.points) std::cout << std::setprecision(6) << ' ' << p.x() << ',' << p.y();
        }
        std::cout << '\n';
    }
}

// Features of every development recording as TSV, for analysis while tuning.
void features(const std::vector<st::Recording>& recs)
{
    namespace sk = sculptline::solvers::stroke;
    std::cout << "subject\tspeed\tnum\tgesture\tkind\tclosed\tcorners\tverts\tsupported\tmaxres\trmsres\tminturn\tcircres\tellres\tellratio\tbow\tcmax\tturn\n";
    for (const auto& r : recs) {
        sk::RecognizeOptions o = gOptions;
        o.regularize = false;
        const sk::StrokeRecognition sr = sk::recognizeStroke(r.stroke, {}, o);
        const sk::FitResult& fit = sr.fit;
        const sk::Recognition& rec = sr.recognition;
        const sk::StrokeGeometry& g = rec.geometry;
        double bow = 0;  // worst deviation from an edge relative to that edge's length
        {
            const auto& idx = g.vertexIndex;
            const int n = static_cast<int>(g.points.size());
            const size_t ne = idx.size() < 2 ? 0 : (g.closed ? idx.size() : idx.size() - 1);
            for (size_t e = 0; e < ne; ++e) {
                const int a = idx[e], b = idx[(e + 1) % idx.size()];
                const auto pa = g.points[a], pb = g.points[b];
                const double len = (pb - pa).norm();
                for (int k = (a + 1) % n; k != b; k = (k + 1) % n) {
                    const auto ab = pb - pa;
                    const double t = len > 0 ? std::clamp((g.points[k] - pa).dot(ab) / (len * len), 0.0, 1.0) : 0.0;
                    bow = std::max(bow, (pa + t * ab - g.points[k]).norm() / std::max(len, 1e-9 * g.extent));
                }
            }
        }
        const sk::StrokeGeometry g0 = sk::strokeGeometry(fit);
        int supported = 0;
        for (int k : g.vertexIndex)
            for (int c : g0.vertexIndex)
                if (std::abs(k - c) <= 2) { ++supported; break; }
        double cmax = 0;  // polyline through the fitter's corners (and the seam of a loop) only
        {
            std::vector<int> ci = g0.vertexIndex;
            if (g0.closed && (ci.empty() || ci.front() != 0)) ci.insert(ci.begin(), 0);
            const size_t ne = ci.size() < 2 ? 0 : (g0.closed ? ci.size() : ci.size() - 1);
            const int n = static_cast<int>(g0.points.size());
            for (size_t e = 0; e < ne; ++e) {
                const int a = ci[e], b = ci[(e + 1) % ci.size()];
                const sculptline::solvers::stroke::Point2 pa = g0.points[a], pb = g0.points[b], ab = pb - pa;
                for (int k = (a + 1) % n; k != b; k = (k + 1) % n) {
                    const double t = ab.squaredNorm() > 0 ? std::clamp((g0.points[k] - pa).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
                    cmax = std::max(cmax, (pa + t * ab - g0.points[k]).norm());
                }
            }
            if (ne == 0) cmax = 1e9;
        }
        double maxres = 0, sum = 0;
        const size_t edges = g.vertices.size() < 2 ? 0 : (g.closed ? g.vertices.size() : g.vertices.size() - 1);
        for (const auto& p : g.points) {
            double best = 1e300;
            for (size_t e = 0; e < edges; ++e) {
                const auto a = g.vertices[e], b = g.vertices[(e + 1) % g.vertices.size()];
                const auto ab = b - a;
                const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
                best = std::min(best, (a + t * ab - p).norm());
            }
            if (edges == 0) best = 0;
            maxres = std::max(maxres, best);
            sum += best * best;
        }
        double minturn = 10;
        const size_t m = g.vertices.size();
        for (size_t v = g.closed ? 0 : 1; m >= 3 && v < (g.closed ? m : m - 1); ++v) {
            const auto a = g.vertices[v] - g.vertices[(v + m - 1) % m], b = g.vertices[(v + 1) % m] - g.vertices[v];
            minturn = std::min(minturn, std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b)));
        }
        const double e = g.extent;
        std::cout << r.subject << '\t' << r.speed << '\t' << r.number << '\t' << r.gesture << '\t' << sk::shapeName(rec.kind) << '\t' << g.closed << '\t'
                  << fit.corners.size() << '\t' << m << '\t' << supported << '\t' << maxres / e << '\t' << std::sqrt(sum / g.points.size()) / e << '\t'
                  << minturn << '\t' << (rec.circle.valid ? rec.circle.maxResidual / e : -1) << '\t' << (rec.ellipse.valid ? rec.ellipse.maxResidual / e : -1) << '\t'
                  << (rec.ellipse.valid ? rec.ellipse.a / rec.ellipse.b : -1) << '\t' << bow << '\t' << cmax / e << '\t' << turnDeg(g.points, rec.circle.center) << '\n';
    }
}

// The fit alone (fitStroke, default options, as recognizeStroke runs it) on every development
// stroke: control points, loops and the time per gesture, for measuring a fitting change on strokes
// people drew (the held-out subjects and Quick, Draw! are not for tuning). With `names`, one line
// per stroke too.
// The fit options of --fit-dev (--no-stray-bound, --no-pieces-searched: FitOptions' switches off).
sculptline::solvers::stroke::FitOptions gFitOptions;

void fitDev(const std::vector<st::Recording>& recs, bool names, const sculptline::solvers::stroke::FitOptions& options)
{
    namespace sk = sculptline::solvers::stroke;
    struct Sum {
        int strokes = 0, points = 0, loops = 0, loopPoints = 0, missed = 0, failed = 0, strays = 0;
        double ms = 0.0;
    };
    std::map<std::string, Sum> by;
    Sum all;
    for (const auto& r : recs) {
        Sum& g = by[r.gesture];
        ++g.strokes;
        ++all.strokes;
        try {
            const auto start = std::chrono::steady_clock::now();
            const sk::FitResult fit = sk::fitStroke(r.stroke, options);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            const bool closed = fit.conditioned.closed;
            // (A closed curve repeats 3 points: scripts/compare_splprep.py counts it so too.)
            const int points = fit.curve.pointCount() - (closed ? 3 : 0);
            for (Sum* s : {&g, &all}) {
                s->points += points;
                s->loops += closed;
                s->loopPoints += closed ? points : 0;
                s->missed += !fit.converged;
                s->strays += fit.stray.excess > 1.0;
                s->ms += ms;
            }
            if (names)
                std::cout << r.subject << ' ' << r.speed << ' ' << r.number << ' ' << r.gesture << ' ' << points
                          << (closed ? " loop " : " open ") << fit.corners.size() << " corners " << std::fixed
                          << std::setprecision(3) << ms << " ms" << (fit.converged ? "" : " beyond") << " stray "
                          << fit.stray.excess << std::defaultfloat << '\n';
        } catch (const std::exception&) {
            ++g.failed;
            ++all.failed;
        }
    }
    std::cout << "| gesture | strokes | control points | loops | loops' control points | beyond tolerance | strays | "
                 "failed | fit ms |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    const auto row = [](const std::string& name, const Sum& s) {
        std::cout << "| " << name << " | " << s.strokes << " | " << s.points << " | " << s.loops << " | "
                  << s.loopPoints << " | " << s.missed << " | " << s.strays << " | " << s.failed << " | " << std::fixed
                  << std::setprecision(1) << s.ms << std::defaultfloat << " |\n";
    };
    for (const auto& [name, s] : by) row(name, s);
    row("**all**", all);
}

// The development strokes drawn otherwise (perturbStroke): which gestures stop being recognized when
// a person rotates, stretches, leaves open or overshoots them, or draws faster. A stress test on the
// development subjects only; each perturbation's accuracy is that of every gesture so perturbed.
void perturbDev(const std::vector<st::Recording>& recs)
{
    struct Row {
        const char* name;
        st::Perturbation p;
    };
    std::vector<Row> rows = {
        {"as drawn", {}},
        {"rotated 15 deg", {15, 1, 0, 0, 1}},
        {"rotated 30 deg", {30, 1, 0, 0, 1}},
        {"rotated 45 deg", {45, 1, 0, 0, 1}},
        {"rotated 60 deg", {60, 1, 0, 0, 1}},
        {"rotated 90 deg", {90, 1, 0, 0, 1}},
        {"x stretched 0.5", {0, 0.5, 0, 0, 1}},
        {"x stretched 0.7", {0, 0.7, 0, 0, 1}},
        {"x stretched 1.5", {0, 1.5, 0, 0, 1}},
        {"x stretched 2", {0, 2, 0, 0, 1}},
        {"x 1.5, rotated 30", {30, 1.5, 0, 0, 1}},
        {"x 1.5, rotated 45", {45, 1.5, 0, 0, 1}},
        {"end cut 3 %", {0, 1, 0.03, 0, 1}},
        {"end cut 6 %", {0, 1, 0.06, 0, 1}},
        {"end cut 10 %", {0, 1, 0.10, 0, 1}},
        {"overshoot 5 %", {0, 1, 0, 0.05, 1}},
        {"overshoot 10 %", {0, 1, 0, 0.10, 1}},
        {"overshoot 15 %", {0, 1, 0, 0.15, 1}},
        {"end extended 3 %", {0, 1, 0, 0, 1, 0.03}},
        {"end extended 6 %", {0, 1, 0, 0, 1, 0.06}},
        {"both ends past the start 3 %", {0, 1, 0, 0, 1, 0.03, 0, 1, 0.03}},
        {"both ends past the start 5 %", {0, 1, 0, 0, 1, 0.05, 0, 1, 0.05}},
        {"corners rounded 4 %", {0, 1, 0, 0, 1, 0, 0.04}},
        {"corners rounded 8 %", {0, 1, 0, 0, 1, 0, 0.08}},
        {"corners rounded 12 %", {0, 1, 0, 0, 1, 0, 0.12}},
        {"sheared 0.3", {0, 1, 0, 0, 1, 0, 0, 1, 0, 0.3}},
        {"sheared 0.5", {0, 1, 0, 0, 1, 0, 0, 1, 0, 0.5}},
        {"tapered 0.4", {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0.4}},
        {"tapered 0.7", {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0.7}},
        {"every 2nd sample", {0, 1, 0, 0, 1, 0, 0, 2}},
        {"every 3rd sample", {0, 1, 0, 0, 1, 0, 0, 3}},
        {"times x0.5", {0, 1, 0, 0, 0.5}},
        {"times x2", {0, 1, 0, 0, 2}},
        {"wavering 1 %, 5 waves", {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0.01, 5}},
        {"wavering 2 %, 5 waves", {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0.02, 5}},
        {"wavering 2 %, 9 waves", {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0.02, 9}},
        {"wavering 3 %, 3 waves", {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0.03, 3}},
    };
    for (const auto& [name, p] : sloppyWays()) rows.push_back({name, p});
    const std::vector<std::string> shown = {"rectangle", "delete_mark", "triangle", "circle", "x", "check", "arrow"};
    std::cout << "| perturbation | all |";
    for (const auto& g : shown) std::cout << ' ' << g << " |";
    std::cout << " lowest other gesture |\n|---|---:|";
    for (size_t i = 0; i < shown.size(); ++i) std::cout << "---:|";
    std::cout << "---|\n";
    for (const Row& row : rows) {
        std::vector<st::Recording> moved = recs;
        for (auto& r : moved) r.stroke = st::perturbStroke(r.stroke, row.p);
        const st::Confusion c = st::evaluate(moved, gOptions);
        std::cout << "| " << row.name << " | " << std::fixed << std::setprecision(1) << 100.0 * c.accuracy() << " % |";
        for (const auto& g : shown) std::cout << ' ' << 100.0 * c.accuracy(g) << " |";
        std::string low;
        double lowAcc = 2;
        for (const auto& [g, unused] : c.rows)
            if (std::find(shown.begin(), shown.end(), g) == shown.end() && c.accuracy(g) < lowAcc) {
                lowAcc = c.accuracy(g);
                low = g;
            }
        std::cout << ' ' << low << ' ' << 100.0 * lowAcc << " |" << std::defaultfloat << std::endl;
    }
}

}  // namespace

int main(int argc, char** argv)
{
    std::string dir = SCULPTLINE_UNISTROKE_DATA;
    bool dev = false, held = false, quickdraw = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--dev")) dev = true;
        else if (!std::strcmp(argv[i], "--held-out")) held = true;
        else if (!std::strcmp(argv[i], "--quickdraw"))
            quickdraw = true;
        else if (!std::strcmp(argv[i], "--data") && i + 1 < argc) dir = argv[++i];
        else if (!std::strcmp(argv[i], "--set") && i + 1 < argc) {  // --set name=value (RecognizeOptions)
            const std::string kv = argv[++i];
            const auto eq = kv.find('=');
            const std::string k = kv.substr(0, eq);
            const double v = std::stod(kv.substr(eq + 1));
            if (!setOption(gOptions, k, v)) {
                std::cerr << "unknown option " << k << '\n';
                return 2;
            }
        } else if (!std::strcmp(argv[i], "--adapt") && i + 1 < argc) {  // --adapt dev|held-out
            const bool h = !std::strcmp(argv[++i], "held-out");
            const auto recs = st::loadUnistrokes(dir, h ? st::heldOutSubjects() : st::devSubjects());
            std::cout << "| first n learned | subject | tested | without habits | with habits | change |\n|---:|---|---:|---:|---:|---:|\n";
            for (int n : {1, 2, 3}) {
                int t = 0, b = 0, a = 0;
                for (const auto& r : st::adaptPerSubject(recs, n, gOptions)) {
                    std::cout << "| " << n << " | " << r.subject << " | " << r.tested << " | " << std::fixed << std::setprecision(1)
                              << 100.0 * r.correctBefore / r.tested << " % | " << 100.0 * r.correctAfter / r.tested << " % | "
                              << std::showpos << 100.0 * (r.correctAfter - r.correctBefore) / r.tested << std::noshowpos << " |\n";
                    t += r.tested;
                    b += r.correctBefore;
                    a += r.correctAfter;
                }
                std::cout << "| " << n << " | **all** | " << t << " | " << 100.0 * b / t << " % | " << 100.0 * a / t << " % | " << std::showpos
                          << 100.0 * (a - b) / t << std::noshowpos << " |\n";
            }
            return 0;
        } else if (!std::strcmp(argv[i], "--invariance") && i + 1 < argc) {  // --invariance dev|held-out
            const bool h = !std::strcmp(argv[++i], "held-out");
            const auto recs = st::loadUnistrokes(dir, h ? st::heldOutSubjects() : st::devSubjects());
            std::cout << "| scale | sample spacing | same class | accuracy original | accuracy transformed | changed (gesture: count) |\n|---:|---:|---:|---:|---:|---|\n";
            for (double scale : {0.1, 1.0, 10.0}) {
                for (double spacing : {0.5, 0.999, 1.0, 2.0}) {
                    if (scale == 1.0 && spacing == 1.0) continue;
                    const st::InvarianceResult r = st::measureInvariance(recs, scale, spacing, gOptions);
                    std::cout << "| " << scale << " | " << spacing << " | " << std::fixed << std::setprecision(1) << 100.0 * r.same / r.total << " % | "
                              << 100.0 * r.correctOriginal / r.total << " % | " << 100.0 * r.correctTransformed / r.total << " % | ";
                    for (const auto& [g, c] : r.transitions) std::cout << g << ": " << c << "  ";
                    std::cout << std::defaultfloat << "|\n";
                }
            }
            return 0;
        } else if (!std::strcmp(argv[i], "--augment")) {  // --loso also on the perturbed copies (perturbDev)
            gAugment = true;
        } else if (!std::strcmp(argv[i], "--augment-rounded")) {  // ... and on copies with rounded corners
            gAugment = gAugmentRounded = true;
        } else if (!std::strcmp(argv[i], "--augment-drawn")) {  // ... and on sheared and tapered copies
            gAugment = gAugmentDrawn = true;
        } else if (!std::strcmp(argv[i], "--augment-sloppy")) {  // ... and on copies drawn two ways at once
            gAugment = gAugmentSloppy = true;
        } else if (!std::strcmp(argv[i], "--loso") && i + 2 < argc) {  // --loso option v1,v2,..
            const std::string k = argv[++i];
            std::vector<double> values;
            std::istringstream list(argv[++i]);
            for (std::string v; std::getline(list, v, ',');) values.push_back(std::stod(v));
            sculptline::solvers::stroke::RecognizeOptions probe;
            if (values.empty() || !setOption(probe, k, values.front())) {
                std::cerr << "--loso: unknown option or no values\n";
                return 2;
            }
            std::vector<st::Recording> recs = st::loadUnistrokes(dir, st::devSubjects());
            if (gAugment) recs = augmented(recs);
            leaveOneSubjectOut(recs, k, values);
            return 0;
        } else if (!std::strcmp(argv[i], "--perturb-dev")) {
            perturbDev(st::loadUnistrokes(dir, st::devSubjects()));
            return 0;
        } else if (!std::strcmp(argv[i], "--no-stray-bound")) {
            gFitOptions.boundStray = false;
        } else if (!std::strcmp(argv[i], "--no-pieces-searched")) {
            gFitOptions.piecesSearched = false;
        } else if (!std::strcmp(argv[i], "--fit-dev")) {
            fitDev(st::loadUnistrokes(dir, st::devSubjects()), std::getenv("FIT_NAMES") != nullptr, gFitOptions);
            return 0;
        } else if (!std::strcmp(argv[i], "--features-dev")) {
            features(st::loadUnistrokes(dir, st::devSubjects()));
            return 0;
        } else if (!std::strcmp(argv[i], "--dump-dev") && i + 1 < argc) {
            dump(st::loadUnistrokes(dir, st::devSubjects()), argv[++i]);
            return 0;
        } else {
            std::cerr << "usage: unistroke-report [--dev] [--held-out] [--quickdraw] [--data DIR] [--set "
                         "option=value].. | --adapt "
                         "dev|held-out | --dump-dev GESTURE | [--no-stray-bound] [--no-pieces-searched] --fit-dev | "
                         "--features-dev | "
                         "--perturb-dev | [--augment] "
                         "[--augment-rounded] [--augment-drawn] --loso OPTION V1,V2,..\n";
            return 2;
        }
    }
    if (!dev && !held && !quickdraw) dev = true;
    if (dev) report("Development subjects s02-s06 (slow, medium, fast)", st::loadUnistrokes(dir, st::devSubjects()));
    if (held) report("Held-out subjects s07-s11 (slow, medium, fast)", st::loadUnistrokes(dir, st::heldOutSubjects()));
    if (quickdraw)
        report("Quick, Draw! one-stroke drawings (tests/data/quickdraw; a test set, never tuned on)",
               st::loadQuickDraw());
    return 0;
}
