#include "solvers/stroke/stroke_synthesis.h"

#include "solvers/math_constants.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::solvers::stroke {
namespace {

constexpr int kDense = 4000;  // reference resolution per shape

Shape fromFunction(const std::function<Eigen::Vector3d(double)>& f, double t0, double t1, bool closed)
{
    Shape s;
    s.closed = closed;
    const int n = closed ? kDense : kDense + 1;
    for (int i = 0; i < n; ++i) s.reference.push_back(f(t0 + (t1 - t0) * i / kDense));
    return s;
}

}  // namespace

Shape lineShape(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return fromFunction([&](double t) { return Eigen::Vector3d(a + t * (b - a)); }, 0.0, 1.0, false);
}

Shape arcShape(const Eigen::Vector3d& c, double r, double a0, double a1)
{
    return fromFunction([&](double t) { return Eigen::Vector3d(c + r * Eigen::Vector3d(std::cos(t), std::sin(t), 0.0)); }, a0, a1, false);
}

Shape circleShape(const Eigen::Vector3d& c, double r, double start)
{
    return fromFunction([&](double t) { return Eigen::Vector3d(c + r * Eigen::Vector3d(std::cos(t), std::sin(t), 0.0)); }, start,
                        start + 2 * kPi, true);
}

Shape teardropShape(double r)
{
    Shape s = fromFunction([&](double t) { return Eigen::Vector3d(r * std::cos(t), r * std::sin(t) * std::sin(0.5 * t), 0.0); }, 0.0,
                           2 * kPi, true);
    s.corners = {0};
    return s;
}

Shape ellipseShape(const Eigen::Vector3d& c, double a, double b, double rot)
{
    const double cr = std::cos(rot), sr = std::sin(rot);
    return fromFunction(
        [&](double t) {
            const double x = a * std::cos(t), y = b * std::sin(t);
            return Eigen::Vector3d(c + Eigen::Vector3d(cr * x - sr * y, sr * x + cr * y, 0.0));
        },
        0.4, 0.4 + 2 * kPi, true);
}

Shape polygonShape(const std::vector<Eigen::Vector3d>& v, bool closed)
{
    Shape s;
    s.closed = closed;
    const size_t edges = closed ? v.size() : v.size() - 1;
    const int per = kDense / static_cast<int>(edges);
    for (size_t e = 0; e < edges; ++e) {
        const Eigen::Vector3d a = v[e], b = v[(e + 1) % v.size()];
        if (e > 0 || closed) s.corners.push_back(static_cast<int>(s.reference.size()));
        for (int i = 0; i < per; ++i) s.reference.push_back(a + (b - a) * (double(i) / per));
    }
    if (!closed) s.reference.push_back(v.back());
    return s;
}

Shape sCurveShape(double size)
{
    return fromFunction([&](double t) { return Eigen::Vector3d(size * t, 0.25 * size * std::sin(2 * kPi * t), 0.0); }, 0.0, 1.0,
                        false);
}

Shape spiralShape(double size, double turns)
{
    return fromFunction(
        [&](double t) {
            const double r = size * (0.15 + 0.85 * t);
            return Eigen::Vector3d(r * std::cos(2 * kPi * turns * t), r * std::sin(2 * kPi * turns * t), 0.0);
        },
        0.0, 1.0, false);
}

Shape flourishShape(double size)
{
    return fromFunction(
        [&](double t) {
            return Eigen::Vector3d(size * t, size * (0.2 * std::sin(3 * kPi * t) + 0.08 * std::sin(8 * kPi * t + 0.5)),
                                   0.0);
        },
        0.0, 1.0, false);
}

Shape hairpinShape(double size, int legs, double turnRadius)
{
    Shape s;
    const int perLeg = kDense / legs;
    const int perTurn = perLeg / 4;
    for (int l = 0; l < legs; ++l) {
        const double x = 2.0 * turnRadius * l;
        const double y0 = l % 2 == 0 ? 0.0 : size, y1 = size - y0;
        const double side = l % 2 == 0 ? -1.0 : 1.0;  // legs bow outwards, alternately
        for (int i = 0; i < perLeg; ++i) {
            const double t = double(i) / perLeg;
            s.reference.emplace_back(x + side * 0.06 * size * std::sin(kPi * t), y0 + (y1 - y0) * t, 0.0);
        }
        if (l + 1 == legs) {
            s.reference.emplace_back(x, y1, 0.0);
            break;
        }
        // Half turn around (x + r, y1), from (x, y1) to (x + 2r, y1), bulging away from the leg.
        const double bulge = l % 2 == 0 ? 1.0 : -1.0;
        for (int i = 0; i < perTurn; ++i) {
            const double a = kPi * i / perTurn;
            if (i == perTurn / 2) s.slowdowns.push_back(static_cast<int>(s.reference.size()));
            s.reference.emplace_back(x + turnRadius * (1.0 - std::cos(a)), y1 + bulge * turnRadius * std::sin(a), 0.0);
        }
    }
    return s;
}

Shape helixShape(double radius, double pitch, double turns)
{
    return fromFunction([&](double t) { return Eigen::Vector3d(radius * std::cos(t), radius * std::sin(t), pitch * t / (2 * kPi)); }, 0.0,
                        2 * kPi * turns, false);
}

Stroke drawWithSamples(const Shape& shape, int samples, DrawOptions o)
{
    const Stroke probe = draw(shape, o);
    o.rate *= std::max(1.0, samples - 1.0) / std::max<double>(1.0, probe.points.size() - 1.0);
    return draw(shape, o);
}

Stroke draw(const Shape& shape, const DrawOptions& o)
{
    const auto& ref = shape.reference;
    const int n = static_cast<int>(ref.size());
    // Speed per reference vertex: two-thirds power law on the discrete curvature, times a dip near
    // corners whose width is a few per cent of the length.
    std::vector<double> arc(n + 1, 0.0);
    const int segs = shape.closed ? n : n - 1;
    for (int i = 0; i < segs; ++i) arc[i + 1] = arc[i] + (ref[(i + 1) % n] - ref[i]).norm();
    const double total = arc[segs];
    std::vector<double> speed(n, o.peakSpeed);
    for (int i = 0; i < n; ++i) {
        const int a = shape.closed ? (i + n - 8) % n : std::max(0, i - 8);
        const int b = shape.closed ? (i + 8) % n : std::min(n - 1, i + 8);
        const Eigen::Vector3d u = ref[i] - ref[a], w = ref[b] - ref[i];
        const double len = u.norm() + w.norm();
        const double turn = (u.norm() > 0 && w.norm() > 0) ? std::atan2(u.cross(w).norm(), u.dot(w)) : 0.0;
        const double kappa = len > 0 ? turn / len : 0.0;
        speed[i] = o.peakSpeed * std::min(1.0, std::pow(1.0 + kappa * total / (2 * kPi), -1.0 / 3.0) * 1.6);
    }
    std::vector<int> slow = shape.corners;
    slow.insert(slow.end(), shape.slowdowns.begin(), shape.slowdowns.end());
    for (int c : slow) {
        for (int i = 0; i < n; ++i) {
            double d = std::abs(arc[i] - arc[c]);
            if (shape.closed) d = std::min(d, total - d);
            const double w = 0.04 * total;
            speed[i] *= 1.0 - (1.0 - o.cornerSlowdown) * std::exp(-(d * d) / (w * w));
        }
    }
    // Ends: the pen accelerates from and decelerates to rest over ~3 % of the length.
    if (!shape.closed) {
        for (int i = 0; i < n; ++i) {
            const double d = std::min(arc[i], total - arc[i]) / (0.03 * total);
            speed[i] *= 0.3 + 0.7 * std::min(1.0, d);
        }
    }
    std::mt19937 rng(o.seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    const double end = shape.closed ? total * (1.0 + o.closureOffset) : total;
    auto at = [&](double s, int* segOut) {
        if (shape.closed) s = std::fmod(s, total);
        const int seg = std::clamp(int(std::upper_bound(arc.begin(), arc.begin() + segs + 1, s) - arc.begin()) - 1, 0,
                                   segs - 1);
        const double h = arc[seg + 1] - arc[seg];
        const double f = h > 0 ? (s - arc[seg]) / h : 0.0;
        *segOut = seg;
        return Eigen::Vector3d(ref[seg] + f * (ref[(seg + 1) % n] - ref[seg]));
    };
    Stroke s;
    const bool planar = std::all_of(ref.begin(), ref.end(), [](const Eigen::Vector3d& p) { return p.z() == 0.0; });
    s.dimension = planar ? 2 : 3;
    const double dt = 1.0 / o.rate;
    double pos = 0.0, t = 0.0;
    while (true) {
        int seg = 0;
        Eigen::Vector3d p = at(pos, &seg);
        // Planar strokes keep the expression (and random stream) they always had; a space shape
        // draws three numbers in a fixed order.
        if (o.noise > 0 && planar) p += o.noise * Eigen::Vector3d(gauss(rng), gauss(rng), 0.0);
        if (o.noise > 0 && !planar) {
            const double nx = gauss(rng), ny = gauss(rng), nz = gauss(rng);
            p += o.noise * Eigen::Vector3d(nx, ny, nz);
        }
        s.points.push_back(p);
        if (o.withTimes) s.times.push_back(t);
        if (pos >= end) break;
        pos = std::min(end, pos + speed[seg] * dt);
        t += dt;
    }
    return s;
}

double distanceToPolyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& poly, bool closed)
{
    double best = std::numeric_limits<double>::infinity();
    const size_t segs = closed ? poly.size() : poly.size() - 1;
    for (size_t i = 0; i < segs; ++i) {
        const Eigen::Vector3d& a = poly[i];
        const Eigen::Vector3d& b = poly[(i + 1) % poly.size()];
        const Eigen::Vector3d ab = b - a;
        const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
        best = std::min(best, (a + t * ab - p).norm());
    }
    return best;
}

}  // namespace sculptline::solvers::stroke
