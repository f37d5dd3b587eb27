#include "unistroke_eval.h"

#include "solvers/stroke/stroke_fitter.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace sculptline::stroketest {

namespace stroke = solvers::stroke;

std::vector<std::string> devSubjects() { return {"s02", "s03", "s04", "s05", "s06"}; }
std::vector<std::string> heldOutSubjects() { return {"s07", "s08", "s09", "s10", "s11"}; }
std::vector<Recording> loadQuickDraw(const std::string& dir)
{
    return loadUnistrokes(dir, {"quickdraw"});
}

std::vector<Recording> loadUnistrokes(const std::string& dir, const std::vector<std::string>& subjects)
{
    std::vector<Recording> out;
    for (const auto& s : subjects) {
        const std::string path = dir + "/" + s + ".csv";
        std::ifstream in(path);
        if (!in) throw std::runtime_error("cannot read " + path);
        std::string line;
        int lineNo = 0;
        while (std::getline(in, line)) {
            ++lineNo;
            if (line.empty()) continue;
            Recording r;
            r.subject = s;
            std::istringstream fields(line);
            std::string number, samples;
            if (!std::getline(fields, r.gesture, ',') || !std::getline(fields, r.speed, ',') ||
                !std::getline(fields, number, ',') || !std::getline(fields, samples)) {
                throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": expected gesture,speed,number,samples");
            }
            r.number = std::stoi(number);
            std::istringstream pts(samples);
            std::string one;
            while (std::getline(pts, one, ';')) {
                double x = 0, y = 0, t = 0;
                std::istringstream p(one);
                if (!(p >> x >> y >> t)) throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": bad sample '" + one + "'");
                r.stroke.points.emplace_back(x, -y, 0.0);  // screen y points down
                r.stroke.times.push_back(t / 1000.0);
            }
            out.push_back(std::move(r));
        }
    }
    return out;
}

const std::vector<ShapeKind>& acceptedKinds(const std::string& gesture)
{
    static const std::map<std::string, std::vector<ShapeKind>> table = {
        {"triangle", {ShapeKind::Triangle}},
        {"rectangle", {ShapeKind::Rectangle, ShapeKind::Square}},
        {"circle", {ShapeKind::Circle, ShapeKind::Ellipse}},
        {"check", {ShapeKind::Polyline}},
        {"caret", {ShapeKind::Polyline}},
        {"v", {ShapeKind::Polyline}},
        {"left_sq_bracket", {ShapeKind::Polyline}},
        {"right_sq_bracket", {ShapeKind::Polyline}},
        {"star", {ShapeKind::Polyline}},
        {"arrow", {ShapeKind::Polyline}},
        {"x", {ShapeKind::Polyline}},
        {"delete_mark", {ShapeKind::Polyline}},
        {"pigtail", {ShapeKind::Freeform}},
        {"question_mark", {ShapeKind::Freeform}},
        // A curly brace is two S-bends meeting at a point: curved, not straight segments.
        {"left_curly_brace", {ShapeKind::Freeform}},
        {"right_curly_brace", {ShapeKind::Freeform}},
        // Quick, Draw! categories (tests/data/quickdraw; circle, triangle and star as above).
        {"square", {ShapeKind::Rectangle, ShapeKind::Square}},  // the rectangle class, as the $1 rectangle
        {"line", {ShapeKind::Line}},
        {"zigzag", {ShapeKind::Polyline}},
        // The recognizer has no class for more than four sides: a hexagon or octagon is a polygon.
        {"hexagon", {ShapeKind::Polyline}},
        {"octagon", {ShapeKind::Polyline}},
    };
    const auto it = table.find(gesture);
    if (it == table.end()) throw std::invalid_argument("unknown gesture " + gesture);
    return it->second;
}

bool isCorrect(const std::string& gesture, ShapeKind kind)
{
    const auto& ok = acceptedKinds(gesture);
    return std::find(ok.begin(), ok.end(), kind) != ok.end();
}

int Confusion::total() const
{
    int n = 0;
    for (const auto& [g, row] : rows)
        for (int c : row) n += c;
    return n;
}

int Confusion::correct() const
{
    int n = 0;
    for (const auto& [g, row] : rows)
        for (int k = 0; k < kKinds; ++k)
            if (isCorrect(g, static_cast<ShapeKind>(k))) n += row[k];
    return n;
}

double Confusion::accuracy() const { return total() ? double(correct()) / total() : 0.0; }

double Confusion::accuracy(const std::string& gesture) const
{
    const auto it = rows.find(gesture);
    if (it == rows.end()) return 0.0;
    int n = 0, ok = 0;
    for (int k = 0; k <= kKinds; ++k) {
        n += it->second[k];
        if (k < kKinds && isCorrect(gesture, static_cast<ShapeKind>(k))) ok += it->second[k];
    }
    return n ? double(ok) / n : 0.0;
}

double Confusion::classAccuracy(ShapeKind kind) const
{
    int n = 0, ok = 0;
    for (const auto& [g, row] : rows) {
        if (acceptedKinds(g).front() != kind) continue;
        for (int k = 0; k <= kKinds; ++k) {
            n += row[k];
            if (k < kKinds && isCorrect(g, static_cast<ShapeKind>(k))) ok += row[k];
        }
    }
    return n ? double(ok) / n : 0.0;
}

std::string Confusion::table() const
{
    static const char* abbrev[kKinds + 1] = {"line", "arc", "circ", "ell", "tri", "rect", "sq", "diam", "poly", "free", "fail"};
    std::ostringstream o;
    o << "| gesture (expected) |";
    for (const char* a : abbrev) o << ' ' << a << " |";
    o << " correct |\n|---|";
    for (int k = 0; k <= kKinds; ++k) o << "---:|";
    o << "---:|\n";
    for (const auto& [g, row] : rows) {
        o << "| " << g << " (" << stroke::shapeName(acceptedKinds(g).front()) << ") |";
        for (int c : row) o << ' ' << (c ? std::to_string(c) : std::string(".")) << " |";
        o << ' ' << std::fixed << std::setprecision(1) << 100.0 * accuracy(g) << " % |\n";
    }
    o << "| **all** |";
    for (int k = 0; k <= kKinds; ++k) o << " |";
    o << " **" << std::fixed << std::setprecision(1) << 100.0 * accuracy() << " %** (" << correct() << "/" << total() << ") |\n";
    return o.str();
}

stroke::FitOptions classFitOptions()
{
    stroke::FitOptions f;
    f.minimaxTrials = false;
    return f;
}

int recognizeRecording(const Recording& r, const stroke::RecognizeOptions& options)
{
    try {
        stroke::RecognizeOptions o = options;
        o.regularize = false;  // the class is what is measured; regularizing does not change it
        return static_cast<int>(stroke::recognizeStroke(r.stroke, classFitOptions(), o).recognition.kind);
    } catch (const std::exception&) {
        return -1;
    }
}

Confusion evaluate(const std::vector<Recording>& recordings, const stroke::RecognizeOptions& options)
{
    Confusion c;
    for (const auto& r : recordings) {
        const int k = recognizeRecording(r, options);
        auto& row = c.rows[r.gesture];
        ++row[k < 0 ? kFailed : k];
    }
    return c;
}

}  // namespace sculptline::stroketest

#include "solvers/stroke/user_model.h"

namespace sculptline::stroketest {

std::vector<AdaptationResult> adaptPerSubject(const std::vector<Recording>& recordings, int firstN,
                                              const stroke::RecognizeOptions& options)
{
    stroke::RecognizeOptions o = options;
    o.regularize = false;
    std::map<std::string, std::vector<const Recording*>> bySubject;
    for (const auto& r : recordings) bySubject[r.subject].push_back(&r);
    std::vector<AdaptationResult> out;
    for (const auto& [subject, recs] : bySubject) {
        AdaptationResult a;
        a.subject = subject;
        stroke::UserModel model = stroke::UserModel::predefined(subject);
        std::vector<std::pair<const Recording*, stroke::StrokeRecognition>> test;
        // Learning in drawing order: the logs number each gesture's repetitions at each speed.
        for (int number = 1; number <= firstN; ++number) {
            for (const Recording* r : recs) {
                if (r->number != number) continue;
                try {
                    stroke::StrokeRecognition sr = stroke::recognizeStroke(r->stroke, classFitOptions(), o);
                    model.applyHabits(sr.recognition, sr.fit, o);
                    // The designer confirms a stroke read as one of its gesture's classes and
                    // corrects any other to the gesture's first class.
                    const ShapeKind kind = sr.recognition.kind;
                    model.learnShape(sr.recognition, isCorrect(r->gesture, kind) ? kind : acceptedKinds(r->gesture).front());
                } catch (const std::exception&) {
                }
                ++a.trained;
            }
        }
        for (const Recording* r : recs) {
            if (r->number <= firstN) continue;
            ++a.tested;
            try {
                stroke::StrokeRecognition sr = stroke::recognizeStroke(r->stroke, classFitOptions(), o);
                a.correctBefore += isCorrect(r->gesture, sr.recognition.kind);
                model.applyHabits(sr.recognition, sr.fit, o);
                a.correctAfter += isCorrect(r->gesture, sr.recognition.kind);
            } catch (const std::exception&) {
            }
        }
        out.push_back(a);
    }
    return out;
}

}  // namespace sculptline::stroketest

namespace sculptline::stroketest {

stroke::Stroke transformStroke(const stroke::Stroke& s, double scale, double spacing)
{
    stroke::Stroke out;
    const size_t n = s.points.size();
    std::vector<double> arc(n, 0.0);
    for (size_t i = 1; i < n; ++i) arc[i] = arc[i - 1] + scale * (s.points[i] - s.points[i - 1]).norm();
    const bool timed = s.times.size() == n;
    if (spacing == 1.0 || n < 2 || arc.back() <= 0.0) {
        for (size_t i = 0; i < n; ++i) out.points.push_back(scale * s.points[i]);
        out.times = s.times;
        return out;
    }
    const double step = spacing * arc.back() / double(n - 1);
    size_t seg = 0;
    for (double a = 0.0; a < arc.back() - 0.5 * step; a += step) {
        while (seg + 2 < n && arc[seg + 1] <= a) ++seg;
        const double len = arc[seg + 1] - arc[seg];
        const double t = len > 0.0 ? std::clamp((a - arc[seg]) / len, 0.0, 1.0) : 0.0;
        out.points.push_back(scale * ((1 - t) * s.points[seg] + t * s.points[seg + 1]));
        if (timed) out.times.push_back((1 - t) * s.times[seg] + t * s.times[seg + 1]);
    }
    out.points.push_back(scale * s.points.back());
    if (timed) out.times.push_back(s.times.back());
    return out;
}

InvarianceResult measureInvariance(const std::vector<Recording>& recordings, double scale, double spacing,
                                   const stroke::RecognizeOptions& options)
{
    InvarianceResult res;
    res.scale = scale;
    res.spacing = spacing;
    for (const auto& r : recordings) {
        Recording t = r;
        t.stroke = transformStroke(r.stroke, scale, spacing);
        const int a = recognizeRecording(r, options), b = recognizeRecording(t, options);
        ++res.total;
        res.same += a == b;
        if (a != b) {
            ++res.changedByGesture[r.gesture];
            const auto name = [](int k) { return std::string(k < 0 ? "failed" : stroke::shapeName(static_cast<ShapeKind>(k))); };
            ++res.transitions[name(a) + "->" + name(b)];
        }
        res.correctOriginal += a >= 0 && isCorrect(r.gesture, static_cast<ShapeKind>(a));
        res.correctTransformed += b >= 0 && isCorrect(r.gesture, static_cast<ShapeKind>(b));
    }
    return res;
}

}  // namespace sculptline::stroketest

#include <cmath>

namespace sculptline::stroketest {

stroke::Stroke perturbStroke(const stroke::Stroke& s, const Perturbation& p)
{
    stroke::Stroke out = s;
    const size_t n = s.points.size();
    if (n < 2) return out;
    const bool timed = s.times.size() == n;
    std::vector<double> arc(n, 0.0);
    for (size_t i = 1; i < n; ++i) arc[i] = arc[i - 1] + (s.points[i] - s.points[i - 1]).norm();
    if (p.cutShare > 0.0) {  // leave off the end: keep the samples up to (1 - cut) of the length
        const double keep = (1.0 - p.cutShare) * arc.back();
        size_t m = 1;
        while (m < n && arc[m] <= keep) ++m;
        out.points.assign(s.points.begin(), s.points.begin() + static_cast<long>(std::max<size_t>(m, 2)));
        if (timed) out.times.assign(s.times.begin(), s.times.begin() + static_cast<long>(out.points.size()));
    }
    if (p.overshootShare > 0.0) {  // back to the start, then on along the stroke's own first part
        const double until = p.overshootShare * arc.back();
        const double t0 = timed ? out.times.back() : 0.0;
        const double speed = timed && s.times.back() > s.times.front() ? arc.back() / (s.times.back() - s.times.front()) : 1.0;
        const double back = (s.points.front() - out.points.back()).norm() / speed;
        for (size_t i = 0; i < n && arc[i] <= until; ++i) {
            out.points.push_back(s.points[i]);
            if (timed) out.times.push_back(t0 + back + s.times[i] - s.times[0]);
        }
    }
    if (p.extendShare > 0.0) {  // straight on past the end, in the direction of the last 5 % of the stroke
        const size_t m = out.points.size();
        size_t k = m - 1;
        double walked = 0.0;
        while (k > 0 && walked < 0.05 * arc.back()) {
            walked += (out.points[k] - out.points[k - 1]).norm();
            --k;
        }
        const Eigen::Vector3d dir = (out.points[m - 1] - out.points[k]).normalized();
        const double step = arc.back() / double(n - 1), dt = timed ? (s.times.back() - s.times.front()) / double(n - 1) : 0.0;
        const Eigen::Vector3d end = out.points.back();
        const double tEnd = timed ? out.times.back() : 0.0;
        for (int j = 1; j * step <= p.extendShare * arc.back(); ++j) {
            out.points.push_back(end + j * step * dir);
            if (timed) out.times.push_back(tEnd + j * dt);
        }
    }
    if (p.leadInShare > 0.0) {  // straight in along the line of the first 5 %, before the first sample
        size_t k = 0;
        while (k + 1 < n && arc[k] < 0.05 * arc.back()) ++k;
        const Eigen::Vector3d dir = (s.points[k] - s.points[0]).normalized();
        const double step = arc.back() / double(n - 1), dt = timed ? (s.times.back() - s.times.front()) / double(n - 1) : 0.0;
        std::vector<Eigen::Vector3d> pts;
        std::vector<double> ts;
        const int lead = static_cast<int>(std::floor(p.leadInShare * arc.back() / step));
        for (int j = lead; j >= 1; --j) {
            pts.push_back(s.points[0] - j * step * dir);
            if (timed) ts.push_back(s.times[0] - j * dt);
        }
        out.points.insert(out.points.begin(), pts.begin(), pts.end());
        if (timed) {
            out.times.insert(out.times.begin(), ts.begin(), ts.end());
            for (auto& t : out.times) t += lead * dt;  // from 0 again
        }
    }
    if (p.roundShare > 0.0 && out.points.size() > 2) {  // box filter along the arc, window shrunk at the ends
        const size_t m = out.points.size();
        std::vector<double> u(m, 0.0);
        for (size_t i = 1; i < m; ++i) u[i] = u[i - 1] + (out.points[i] - out.points[i - 1]).norm();
        const double half = 0.5 * p.roundShare * u.back();
        std::vector<Eigen::Vector3d> q(m);
        for (size_t i = 0; i < m; ++i) {
            const double w = std::min({half, u[i], u.back() - u[i]});
            // The mean of the polyline over [u_i - w, u_i + w], each segment weighted by its length inside.
            Eigen::Vector3d acc = Eigen::Vector3d::Zero();
            double len = 0.0;
            for (size_t k = 1; k < m; ++k) {
                const double a = std::max(u[k - 1], u[i] - w), b = std::min(u[k], u[i] + w);
                if (b <= a || u[k] <= u[k - 1]) continue;
                const double ta = (a - u[k - 1]) / (u[k] - u[k - 1]), tb = (b - u[k - 1]) / (u[k] - u[k - 1]);
                const Eigen::Vector3d pa = out.points[k - 1] + ta * (out.points[k] - out.points[k - 1]);
                const Eigen::Vector3d pb = out.points[k - 1] + tb * (out.points[k] - out.points[k - 1]);
                acc += 0.5 * (b - a) * (pa + pb);
                len += b - a;
            }
            q[i] = len > 0.0 ? Eigen::Vector3d(acc / len) : out.points[i];
        }
        out.points = q;
    }
    if (p.wobble > 0.0 && out.points.size() > 2) {  // along the normal of the chord of each sample's neighbours
        const size_t m = out.points.size();
        Eigen::Vector3d lo = out.points[0], hi = out.points[0];
        for (const auto& q : out.points) {
            lo = lo.cwiseMin(q);
            hi = hi.cwiseMax(q);
        }
        const double extent = (hi - lo).head<2>().maxCoeff();
        std::vector<double> u(m, 0.0);
        for (size_t i = 1; i < m; ++i) u[i] = u[i - 1] + (out.points[i] - out.points[i - 1]).norm();
        std::vector<Eigen::Vector3d> q = out.points;
        for (size_t i = 0; i < m; ++i) {
            const Eigen::Vector3d t = out.points[std::min(i + 1, m - 1)] - out.points[i > 0 ? i - 1 : 0];
            if (t.head<2>().norm() <= 0.0 || u.back() <= 0.0) continue;
            const Eigen::Vector3d normal(-t.y() / t.head<2>().norm(), t.x() / t.head<2>().norm(), 0.0);
            q[i] +=
                p.wobble * extent * std::sin(2.0 * 3.14159265358979323846 * p.wobbleWaves * u[i] / u.back()) * normal;
        }
        out.points = q;
    }
    if (p.keepEvery > 1 && out.points.size() > 2) {
        stroke::Stroke kept;
        const size_t m = out.points.size();
        for (size_t i = 0; i < m; ++i) {
            if (i % static_cast<size_t>(p.keepEvery) != 0 && i + 1 != m) continue;
            kept.points.push_back(out.points[i]);
            if (out.times.size() == m) kept.times.push_back(out.times[i]);
        }
        out.points = kept.points;
        out.times = kept.times;
    }
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& q : out.points) c += q;
    c /= double(out.points.size());
    const double a = p.rotateDeg * 3.14159265358979323846 / 180.0, ca = std::cos(a), sa = std::sin(a);
    double ylo = c.y(), yhi = c.y();
    for (const auto& q : out.points) {
        ylo = std::min(ylo, q.y());
        yhi = std::max(yhi, q.y());
    }
    const double height = yhi > ylo ? yhi - ylo : 1.0;
    for (auto& q : out.points) {  // stretched (sheared, tapered), then rotated: a rectangle stays a rectangle
        const double y = q.y() - c.y();
        const double x = (q.x() - c.x()) * (1.0 - p.taper * y / height) + p.shear * y;
        const Eigen::Vector3d d(p.aspect * x, y, q.z() - c.z());
        q = c + Eigen::Vector3d(ca * d.x() - sa * d.y(), sa * d.x() + ca * d.y(), d.z());
    }
    for (auto& t : out.times) t *= p.timeScale;
    return out;
}

}  // namespace sculptline::stroketest
