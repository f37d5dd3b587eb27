#include "solvers/aesthetics/curve_analysis.h"

#include "solvers/bspline/arc_length.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/geometry/plane_fit.h"
#include "solvers/incidence/bernstein.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::solvers::aesthetics {
namespace {

using Poly = Eigen::VectorXd;  // Bernstein coefficients on [0, 1]
using incidence::bernsteinProduct;
using incidence::bernsteinRoots;
using incidence::bernsteinValue;

// A polynomial counts as zero where it is within this fraction of the largest coefficient of the
// products it was summed from: far above their round-off (about 1e-15 of that scale after a few
// dozen operations), far below any curvature change a designer could see. An exact circle (a
// rational quadratic) gives kappa' identically zero and thus no extrema; a cubic's near-circle keeps
// its real extrema.
constexpr double kZeroRelative = 1e-9;
// Samples per knot span for the sampled measures: the enclosing rectangle and the crown are within
// the chord error of 32 samples of a span (1e-3 of the size on a quarter ellipse).
constexpr int kSamplesPerSpan = 32;
// Tangents per span for the total turning, which is exact while each step turns less than pi: a
// span of a fair curve turns far less than 8 pi.
constexpr int kTurningStepsPerSpan = 8;
// Bisection steps for the ranges of influence: 52 halvings bring a parameter interval to round-off.
constexpr int kBisections = 52;

Poly derivative(const Poly& c)
{
    const int n = static_cast<int>(c.size()) - 1;
    if (n <= 0) return Poly::Zero(1);
    Poly d(n);
    for (int k = 0; k < n; ++k) d[k] = n * (c[k + 1] - c[k]);
    return d;
}

// Degree elevation to `degree` (Farin §5.1): c'_k = k/(n+1) c_{k-1} + (1 - k/(n+1)) c_k, repeated.
Poly elevated(Poly c, int degree)
{
    while (static_cast<int>(c.size()) - 1 < degree) {
        const int n1 = static_cast<int>(c.size());  // new degree
        Poly e(n1 + 1);
        e[0] = c[0];
        e[n1] = c[n1 - 1];
        for (int k = 1; k < n1; ++k) {
            const double a = double(k) / n1;
            e[k] = a * c[k - 1] + (1.0 - a) * c[k];
        }
        c = e;
    }
    return c;
}

// A sum of signed products that remembers the largest coefficient of its terms: the scale against
// which its own value is zero (kZeroRelative).
struct Sum {
    Poly value = Poly::Zero(1);
    double scale = 0.0;
    void add(const Poly& term, double factor)
    {
        const int degree = std::max<int>(static_cast<int>(value.size()), static_cast<int>(term.size())) - 1;
        value = elevated(value, degree) + factor * elevated(term, degree);
        scale = std::max(scale, std::abs(factor) * term.cwiseAbs().maxCoeff());
    }
    double tolerance() const { return kZeroRelative * scale; }
};

Poly mul(const Poly& a, const Poly& b) { return bernsteinProduct(a, b); }

// On one polynomial piece: `turn` has the sign of kappa (x'y'' - y'x'', or for rational curves the
// determinant of the homogeneous point and its two derivatives, divided by W^3 > 0), `change` the sign
// of d kappa / du.
struct PiecePolys {
    Sum turn, change;
};

// The Bezier pieces of a curve, each as its p + 1 (homogeneous) control rows: every interior
// breakpoint raised to multiplicity p by one knot refinement (The NURBS Book A5.6), O(n p) for all.
std::vector<ControlMatrix> bezierPieces(const Curve2d& curve, const std::vector<double>& breaks)
{
    const Curve2d open = curve.isClosed() ? curve.openAt(curve.domainStart()) : curve.clamped();
    const int p = open.degree();
    std::vector<double> x;
    for (size_t i = 1; i + 1 < breaks.size(); ++i) {
        const int m = knotMultiplicity(open.knots(), breaks[i]);
        for (int k = m; k < p; ++k) x.push_back(breaks[i]);
    }
    const ControlMatrix h = (x.empty() ? open : open.refine(x)).homogeneous();
    std::vector<ControlMatrix> pieces;
    for (size_t i = 0; i + 1 < breaks.size(); ++i) pieces.push_back(h.middleRows(i * p, p + 1));
    return pieces;
}

PiecePolys piecePolynomials(const ControlMatrix& h, bool rational)
{
    const Poly X = h.col(0), Y = h.col(1);
    const Poly X1 = derivative(X), Y1 = derivative(Y), X2 = derivative(X1), Y2 = derivative(Y1);
    PiecePolys p;
    if (!rational) {
        // kappa = D / S^(3/2), D = x'y'' - y'x'', S = x'^2 + y'^2; kappa' has the sign of 2 D' S - 3 D S'.
        p.turn.add(mul(X1, Y2), 1.0);
        p.turn.add(mul(Y1, X2), -1.0);
        const Poly& D = p.turn.value;
        const Poly S = mul(X1, X1) + mul(Y1, Y1);
        p.change.add(mul(derivative(D), S), 2.0);
        p.change.add(mul(D, derivative(S)), -3.0);
        return p;
    }
    // Rational: C = (X, Y) / W. With Det = det[(X, Y, W); (X', Y', W'); (X'', Y'', W'')],
    // A = X'W - XW', B = Y'W - YW', S = A^2 + B^2: kappa = W^3 Det / S^(3/2), and kappa' has the sign of
    // 2 (3 W' Det + W Det') S - 3 W Det S' (W > 0).
    const Poly W = h.col(2);
    const Poly W1 = derivative(W), W2 = derivative(W1);
    p.turn.add(mul(X, mul(Y1, W2)), 1.0);
    p.turn.add(mul(X, mul(W1, Y2)), -1.0);
    p.turn.add(mul(Y, mul(X1, W2)), -1.0);
    p.turn.add(mul(Y, mul(W1, X2)), 1.0);
    p.turn.add(mul(W, mul(X1, Y2)), 1.0);
    p.turn.add(mul(W, mul(Y1, X2)), -1.0);
    const Poly& Det = p.turn.value;
    Sum A, B;
    A.add(mul(X1, W), 1.0);
    A.add(mul(X, W1), -1.0);
    B.add(mul(Y1, W), 1.0);
    B.add(mul(Y, W1), -1.0);
    const Poly S = mul(A.value, A.value) + mul(B.value, B.value);
    Sum inner;
    inner.add(mul(W1, Det), 3.0);
    inner.add(mul(W, derivative(Det)), 1.0);
    p.change.add(mul(inner.value, S), 2.0);
    p.change.add(mul(mul(W, Det), derivative(S)), -3.0);
    p.change.scale = std::max(p.change.scale, 2.0 * inner.scale * S.cwiseAbs().maxCoeff());
    return p;
}

// A stretch of the domain over which a polynomial has one sign (0: zero to kZeroRelative).
struct Stretch {
    double u0, u1;
    int sign;
};

int signOf(double v, double tolerance) { return std::abs(v) <= tolerance ? 0 : (v > 0.0 ? 1 : -1); }

// Appends the sign stretches of `s` on the piece [a, b] (local parameter t = (u - a) / (b - a)).
void appendStretches(const Sum& s, double a, double b, std::vector<Stretch>& out)
{
    const double tol = s.tolerance();
    std::vector<double> cuts{0.0};
    if (s.value.cwiseAbs().maxCoeff() > tol) {
        for (double r : bernsteinRoots(s.value, tol)) {
            if (r > cuts.back()) cuts.push_back(r);
        }
    }
    if (cuts.back() < 1.0) cuts.push_back(1.0);
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double t = 0.5 * (cuts[i] + cuts[i + 1]);
        const int sign = signOf(bernsteinValue(s.value, t), tol);
        const double u0 = a + (b - a) * cuts[i], u1 = a + (b - a) * cuts[i + 1];
        if (!out.empty() && out.back().sign == sign) {
            out.back().u1 = u1;
        } else {
            out.push_back({u0, u1, sign});
        }
    }
}

// Where the sign changes: between two stretches of opposite sign, at their common end or, across a
// zero stretch, at its middle. `from` is the sign before. Open curves: nothing at the ends; closed
// curves: the sequence is cyclic over one period.
struct SignChange {
    double u;
    int from;
};

std::vector<SignChange> signChanges(std::vector<Stretch> st, bool closed, double period)
{
    std::vector<SignChange> out;
    // Merge neighbours of equal sign (appendStretches merges within a piece and across pieces already).
    const auto firstNonZero = std::find_if(st.begin(), st.end(), [](const Stretch& s) { return s.sign != 0; });
    if (firstNonZero == st.end()) return out;
    if (closed) {
        // Rotate so that the sequence starts with a signed stretch; the ones before move a period on.
        std::vector<Stretch> rotated(firstNonZero, st.end());
        for (auto it = st.begin(); it != firstNonZero; ++it) rotated.push_back({it->u0 + period, it->u1 + period, it->sign});
        st = rotated;
        // The stretch after the last is the first, a period on.
        st.push_back({st.front().u0 + period, st.front().u1 + period, st.front().sign});
    }
    int last = 0;
    double zeroStart = 0.0;
    bool inZero = false;
    for (const Stretch& s : st) {
        if (s.sign == 0) {
            if (!inZero) zeroStart = s.u0;
            inZero = true;
            continue;
        }
        if (last != 0 && s.sign != last) out.push_back({inZero ? 0.5 * (zeroStart + s.u0) : s.u0, last});
        inZero = false;
        last = s.sign;
    }
    return out;
}

std::vector<double> distinctBreaks(const Curve2d& c)
{
    std::vector<double> b{c.domainStart()};
    for (double k : c.knots()) {
        if (k > b.back() && k < c.domainEnd()) b.push_back(k);
    }
    b.push_back(c.domainEnd());
    return b;
}

double wrapped(const Curve2d& c, double u) { return c.isClosed() ? c.normalizeParameter(u) : u; }

// Curvature and its arc-length derivative at u (The NURBS Book A3.2/A4.2 derivatives).
struct Jet {
    double kappa = 0.0, dkds = 0.0, speed = 0.0;
};

Jet curvatureJet(const Curve2d& c, double u)
{
    const auto d = c.derivatives(wrapped(c, u), 3);
    Jet j;
    const double S = d[1].squaredNorm();
    j.speed = std::sqrt(S);
    if (j.speed <= std::numeric_limits<double>::min() * 1e10) return j;
    const double D = d[1].x() * d[2].y() - d[1].y() * d[2].x();
    const double D1 = d[1].x() * d[3].y() - d[1].y() * d[3].x();
    const double S1 = 2.0 * d[1].dot(d[2]);
    j.kappa = D / (S * j.speed);
    j.dkds = (D1 * S - 1.5 * D * S1) / (S * S * j.speed) / j.speed;
    return j;
}

// Samples of the curve: every span at kSamplesPerSpan + 1 parameters (ends shared).
std::vector<Eigen::Vector2d> sampleCurve(const Curve2d& c, const std::vector<double>& breaks)
{
    std::vector<Eigen::Vector2d> pts;
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
        for (int k = (i == 0 ? 0 : 1); k <= kSamplesPerSpan; ++k) {
            pts.push_back(c.evaluate(breaks[i] + (breaks[i + 1] - breaks[i]) * k / kSamplesPerSpan));
        }
    }
    return pts;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The convex hull (Andrew's monotone chain), counter-clockwise.
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> p)
{
    std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    if (p.size() < 3) return p;
    std::vector<Eigen::Vector2d> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0.0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0.0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

// Sides of the minimum-area enclosing rectangle: one side lies on a hull edge (Freeman & Shapira
// 1975), so every edge direction is tried (O(h^2) on at most a few thousand hull points).
std::pair<double, double> enclosingRectangle(const std::vector<Eigen::Vector2d>& samples)
{
    const auto hull = convexHull(samples);
    if (hull.size() < 2) return {0.0, 0.0};
    double bestArea = std::numeric_limits<double>::infinity();
    std::pair<double, double> best{0.0, 0.0};
    for (size_t i = 0; i < hull.size(); ++i) {
        Eigen::Vector2d e = hull[(i + 1) % hull.size()] - hull[i];
        if (e.norm() == 0.0) continue;
        e.normalize();
        const Eigen::Vector2d n(-e.y(), e.x());
        double a0 = std::numeric_limits<double>::infinity(), a1 = -a0, b0 = a0, b1 = -a0;
        for (const auto& q : hull) {
            a0 = std::min(a0, q.dot(e));
            a1 = std::max(a1, q.dot(e));
            b0 = std::min(b0, q.dot(n));
            b1 = std::max(b1, q.dot(n));
        }
        const double area = (a1 - a0) * (b1 - b0);
        if (area < bestArea) {
            bestArea = area;
            best = {std::min(a1 - a0, b1 - b0), std::max(a1 - a0, b1 - b0)};
        }
    }
    return best;
}

// Signed area enclosed by the curve and its chord (the end back to the start), counter-clockwise
// positive: 1/2 of the integral of x y' - y x' along the curve plus the chord's term, by 8-point
// Gauss-Legendre per span (exact for non-rational cubics, whose integrand has degree 5).
double signedArea(const Curve2d& c, const std::vector<double>& breaks)
{
    static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    double area = 0.0;
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
        const double mid = 0.5 * (breaks[i] + breaks[i + 1]), half = 0.5 * (breaks[i + 1] - breaks[i]);
        for (int k = 0; k < 4; ++k) {
            for (double s : {-1.0, 1.0}) {
                const auto d = c.derivatives(mid + s * half * x[k], 1);
                area += 0.5 * w[k] * half * cross(d[0], d[1]);
            }
        }
    }
    const Eigen::Vector2d p0 = c.evaluate(c.domainStart()), p1 = c.evaluate(c.domainEnd());
    return area + 0.5 * cross(p1, p0);
}

// The parameter between ua and ub (ua < ub, kappa monotone there) where kappa = target, by bisection.
double solveCurvature(const Curve2d& c, double ua, double ub, double target)
{
    const double ka = signedCurvature(c, wrapped(c, ua));
    for (int i = 0; i < kBisections; ++i) {
        const double um = 0.5 * (ua + ub);
        const double km = signedCurvature(c, wrapped(c, um));
        if ((km - target) * (ka - target) > 0.0) {
            ua = um;
        } else {
            ub = um;
        }
    }
    return 0.5 * (ua + ub);
}

bool isExtremum(PointKind k) { return k != PointKind::Inflection; }
bool isPositive(PointKind k) { return k == PointKind::MaxPositive || k == PointKind::MinPositive; }

}  // namespace

const char* codon(PointKind kind)
{
    switch (kind) {
    case PointKind::MaxPositive: return "M+";
    case PointKind::MinPositive: return "m+";
    case PointKind::MaxNegative: return "M-";
    case PointKind::MinNegative: return "m-";
    case PointKind::Inflection: return "0";
    }
    return "?";
}

PointKind reversed(PointKind kind)
{
    switch (kind) {
    case PointKind::MaxPositive: return PointKind::MinNegative;
    case PointKind::MinPositive: return PointKind::MaxNegative;
    case PointKind::MaxNegative: return PointKind::MinPositive;
    case PointKind::MinNegative: return PointKind::MaxPositive;
    case PointKind::Inflection: return PointKind::Inflection;
    }
    return kind;
}

std::string curveName(const std::vector<PointKind>& kinds, bool closed)
{
    const auto spell = [](const std::vector<PointKind>& k, size_t start) {
        std::string s;
        for (size_t i = 0; i < k.size(); ++i) s += codon(k[(start + i) % k.size()]);
        return s;
    };
    if (!closed || kinds.empty()) return spell(kinds, 0);
    std::vector<PointKind> back(kinds.rbegin(), kinds.rend());
    for (auto& k : back) k = reversed(k);
    std::string best = spell(kinds, 0);
    for (size_t r = 0; r < kinds.size(); ++r) {
        best = std::min({best, spell(kinds, r), spell(back, r)});
    }
    return best;
}

double signedCurvature(const Curve2d& curve, double u)
{
    const auto d = curve.derivatives(u, 2);
    const double speed = d[1].norm();
    if (speed <= std::numeric_limits<double>::min() * 1e10) return 0.0;
    return cross(d[1], d[2]) / (speed * speed * speed);
}

namespace {

// The points; their arc lengths only when asked (the quadrature is most of the cost of a name).
std::vector<CharacteristicPoint> findPoints(const Curve2d& input, bool withArcLengths)
{
    if (input.degree() < 2) throw GeometryError("degree: a curve of degree 1 has no curvature to analyze");
    if (input.degree() > kMaxAnalysisDegree) {
        throw GeometryError("degree: " + std::to_string(input.degree()) + " is above " + std::to_string(kMaxAnalysisDegree) +
                            ", the highest the exact analysis handles");
    }
    if (input.pointCount() > kMaxAnalysisPoints) {
        throw GeometryError("points: " + std::to_string(input.pointCount()) + " control points, the analysis takes at most " +
                            std::to_string(kMaxAnalysisPoints));
    }
    if (input.isCollapsed()) throw GeometryError("curve: its control points coincide (no curvature)");
    // Curvature does not change with translation; centred, the homogeneous products of a rational
    // curve do not carry the size of its distance from the origin into the zero test.
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto& p : input.points()) centre += p;
    centre /= double(input.pointCount());
    std::vector<Eigen::Vector2d> pts;
    for (const auto& p : input.points()) pts.push_back(p - centre);
    const Curve2d curve(input.degree(), input.knots(), pts, input.weights(), input.isClosed());

    const auto breaks = distinctBreaks(curve);
    std::vector<Stretch> turn, change;
    const auto pieces = bezierPieces(curve, breaks);
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
        const PiecePolys p = piecePolynomials(pieces[i], curve.isRational());
        appendStretches(p.turn, breaks[i], breaks[i + 1], turn);
        appendStretches(p.change, breaks[i], breaks[i + 1], change);
    }
    const double period = curve.domainEnd() - curve.domainStart();
    std::vector<CharacteristicPoint> out;
    for (const SignChange& s : signChanges(turn, curve.isClosed(), period)) {
        out.push_back({wrapped(curve, s.u), PointKind::Inflection, 0.0, 0.0});
    }
    for (const SignChange& s : signChanges(change, curve.isClosed(), period)) {
        const double u = wrapped(curve, s.u);
        const double k = signedCurvature(curve, u);
        const bool max = s.from > 0;
        const PointKind kind = max ? (k >= 0.0 ? PointKind::MaxPositive : PointKind::MaxNegative)
                                   : (k >= 0.0 ? PointKind::MinPositive : PointKind::MinNegative);
        out.push_back({u, kind, k, 0.0});
    }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.u < b.u; });
    for (auto& p : out) {
        if (p.kind == PointKind::Inflection) p.curvature = signedCurvature(curve, p.u);
    }
    if (withArcLengths) {
        const ArcLengthParameterization<2> arc(curve);
        for (auto& p : out) p.arcLength = arc.lengthAt(p.u);
    }
    return out;
}

}  // namespace

std::vector<CharacteristicPoint> characteristicPoints(const Curve2d& curve) { return findPoints(curve, true); }

std::string nameOf(const Curve2d& curve)
{
    std::vector<PointKind> kinds;
    for (const auto& p : findPoints(curve, false)) kinds.push_back(p.kind);
    return curveName(kinds, curve.isClosed());
}

CurveAnalysis analyzeCurve(const Curve2d& curve, const Thresholds& thresholds)
{
    CurveAnalysis a;
    a.points = characteristicPoints(curve);
    a.closed = curve.isClosed();
    const ArcLengthParameterization<2> arc(curve);
    a.length = arc.totalLength();
    const double L = a.length;
    const auto positive = [](const std::optional<double>& v, const char* field, double fallback) {
        if (!v) return fallback;
        if (!std::isfinite(*v) || *v <= 0.0) throw GeometryError(std::string("thresholds.") + field + ": must be a positive number");
        return *v;
    };
    a.gamma = positive(thresholds.distance, "distance", kDefaultDistanceFraction * L);
    a.beta = positive(thresholds.curvature, "curvature", kDefaultCurvatureTimesLength / L);
    a.mu = positive(thresholds.sharp, "sharp", kDefaultSharpTimesLength / L);

    std::vector<PointKind> kinds;
    for (const auto& p : a.points) kinds.push_back(p.kind);
    a.name = curveName(kinds, a.closed);

    // Characteristics of each extremum.
    const int n = static_cast<int>(a.points.size());
    const double u0 = curve.domainStart(), u1 = curve.domainEnd(), period = u1 - u0;
    struct Side {
        bool point;  // a characteristic point (else the curve's end)
        int index;
        double u, kappa, s;
    };
    const auto side = [&](int i, int step) -> Side {
        const int j = i + step;
        if (a.closed && n > 0) {
            const int k = ((j % n) + n) % n;
            const auto& p = a.points[k];
            double u = p.u, s = p.arcLength;
            if (step < 0 && (j < 0 || k == i)) u -= period, s -= L;
            if (step > 0 && (j >= n || k == i)) u += period, s += L;
            return {true, k, u, p.curvature, s};
        }
        if (j < 0) return {false, -1, u0, signedCurvature(curve, u0), 0.0};
        if (j >= n) return {false, -1, u1, signedCurvature(curve, u1), L};
        return {true, j, a.points[j].u, a.points[j].curvature, a.points[j].arcLength};
    };
    for (int i = 0; i < n; ++i) {
        const auto& p = a.points[i];
        if (!isExtremum(p.kind)) continue;
        const Side l = side(i, -1), r = side(i, 1);
        Characteristics c;
        c.point = i;
        c.dkLeft = p.curvature - l.kappa;
        c.dkRight = p.curvature - r.kappa;
        c.dLeft = p.arcLength - l.s;
        c.dRight = r.s - p.arcLength;
        const double uL = solveCurvature(curve, l.u, p.u, p.curvature - 0.5 * c.dkLeft);
        const double uR = solveCurvature(curve, p.u, r.u, p.curvature - 0.5 * c.dkRight);
        const auto lengthBetween = [&](double ua, double ub) {
            if (ua < u0) ua += period, ub += period;
            return arcLength(curve, ua, ub);
        };
        c.rangeLeft = lengthBetween(uL, p.u);
        c.rangeRight = lengthBetween(p.u, uR);
        const double aL = std::abs(c.dkLeft), aR = std::abs(c.dkRight);
        c.smallVisibility = (c.dLeft < a.gamma || c.dRight < a.gamma) && (aL < a.beta || aR < a.beta);
        c.sharpCorner = c.dLeft + c.dRight < a.gamma && aL > a.mu && aR > a.mu;
        // Symmetric: equal to 5 % (a difference the eye does not see on a curvature plot).
        constexpr double kSymmetric = 0.05;
        c.symmetric = l.point && r.point && a.points[l.index].kind == a.points[r.index].kind &&
                      std::abs(aL - aR) <= kSymmetric * std::max(aL, aR) &&
                      std::abs(c.dLeft - c.dRight) <= kSymmetric * std::max(c.dLeft, c.dRight);
        c.redundant = l.point && r.point && isExtremum(a.points[l.index].kind) && isExtremum(a.points[r.index].kind) &&
                      isPositive(a.points[l.index].kind) == isPositive(p.kind) &&
                      isPositive(a.points[r.index].kind) == isPositive(p.kind) && std::min(c.dLeft, c.dRight) < a.gamma;
        a.characteristics.push_back(c);
    }

    // Measures. Extreme curvature: at the extrema, the ends and (for a curve without extrema) anywhere.
    Measures& m = a.measures;
    struct At {
        double kappa, s;
    };
    std::vector<At> candidates{{signedCurvature(curve, u0), 0.0}};
    if (!a.closed) candidates.push_back({signedCurvature(curve, u1), L});
    for (const auto& p : a.points) candidates.push_back({p.curvature, p.arcLength});
    const auto [lo, hi] = std::minmax_element(candidates.begin(), candidates.end(),
                                              [](const At& x, const At& y) { return x.kappa < y.kappa; });
    m.curvatureMin = lo->kappa;
    m.curvatureMax = hi->kappa;
    m.sharpness = std::max(std::abs(m.curvatureMin), std::abs(m.curvatureMax));
    double between = std::abs(hi->s - lo->s);
    if (a.closed) between = std::min(between, L - between);
    m.acceleration = between > 0.0 ? (m.curvatureMax - m.curvatureMin) / between : 0.0;

    // Total turning: the tangent's angle summed over steps that each turn less than pi (exact).
    const auto breaks = distinctBreaks(curve);
    double turning = 0.0;
    Eigen::Vector2d prev = curve.derivatives(u0, 1)[1];
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
        for (int k = 1; k <= kTurningStepsPerSpan; ++k) {
            const Eigen::Vector2d t = curve.derivatives(breaks[i] + (breaks[i + 1] - breaks[i]) * k / kTurningStepsPerSpan, 1)[1];
            turning += std::atan2(cross(prev, t), prev.dot(t));
            prev = t;
        }
    }
    m.curvatureAverage = turning / L;
    // A turning of less than 1e-9 rad is round-off of a curve whose turns cancel: no average to divide by.
    constexpr double kNoTurning = 1e-9;
    if (std::abs(turning) > kNoTurning) m.tension = (m.curvatureMax - m.curvatureMin) / m.curvatureAverage;

    const auto samples = sampleCurve(curve, breaks);
    const auto [dmin, dmax] = enclosingRectangle(samples);
    const double ratio = dmax > 0.0 ? dmin / dmax : 0.0;
    m.flatness = 1.0 - ratio;
    m.convexity = signedArea(curve, breaks) * ratio;
    if (!a.closed) {
        const Eigen::Vector2d p0 = samples.front(), chord = samples.back() - p0;
        if (chord.norm() > 0.0) {
            const Eigen::Vector2d dir = chord.normalized();
            for (const auto& q : samples) {
                const double h = cross(dir, q - p0);
                if (std::abs(h) > std::abs(m.crown)) m.crown = h;
            }
        }
    }

    // The logarithmic curvature graph of each monotone segment: between consecutive characteristic
    // points (and the ends), the middle 80 % sampled (at an extremum dkappa/ds vanishes and the graph
    // runs off to infinity).
    std::vector<double> cuts{u0};
    for (const auto& p : a.points) cuts.push_back(p.u);
    cuts.push_back(u1);
    if (a.closed && !a.points.empty()) {
        cuts.clear();
        for (const auto& p : a.points) cuts.push_back(p.u);
        cuts.push_back(a.points.front().u + period);
    }
    constexpr int kLcgSamples = 64;
    constexpr double kLcgTrim = 0.1;
    constexpr int kLcgMinSamples = 8;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        std::vector<double> xs, ys;
        for (int k = 0; k < kLcgSamples; ++k) {
            const double t = kLcgTrim + (1.0 - 2.0 * kLcgTrim) * (k + 0.5) / kLcgSamples;
            const Jet j = curvatureJet(curve, cuts[i] + (cuts[i + 1] - cuts[i]) * t);
            const double ak = std::abs(j.kappa), ad = std::abs(j.dkds);
            // Below these the logarithms measure round-off: a straight piece, a constant-curvature piece.
            if (ak * L < 1e-9 || ad * L * L < 1e-9) continue;
            xs.push_back(-std::log(ak));
            ys.push_back(std::log(ak / ad));
        }
        if (static_cast<int>(xs.size()) < kLcgMinSamples) continue;
        const Eigen::Map<Eigen::VectorXd> X(xs.data(), xs.size()), Y(ys.data(), ys.size());
        const double mx = X.mean(), my = Y.mean();
        const double sxx = (X.array() - mx).square().sum(), sxy = ((X.array() - mx) * (Y.array() - my)).sum();
        const double syy = (Y.array() - my).square().sum();
        if (sxx <= 0.0) continue;
        LcgSegment seg;
        seg.u0 = wrapped(curve, cuts[i]);
        seg.u1 = wrapped(curve, cuts[i + 1]);
        seg.slope = sxy / sxx;
        seg.r2 = syy > 0.0 ? sxy * sxy / (sxx * syy) : 1.0;
        seg.samples = static_cast<int>(xs.size());
        a.lcg.push_back(seg);
    }
    return a;
}

Curve2d planarCurve(const Curve3d& curve, double flatness, PlaneFrame* frame)
{
    const double size = std::max(curve.controlSize(), std::numeric_limits<double>::min());
    std::vector<Eigen::Vector3d> pts(curve.points().begin(), curve.points().end());
    double zmin = pts.front().z(), zmax = zmin;
    for (const auto& p : pts) zmin = std::min(zmin, p.z()), zmax = std::max(zmax, p.z());
    std::vector<Eigen::Vector2d> flat;
    if (zmax - zmin <= flatness * size) {
        for (const auto& p : pts) flat.emplace_back(p.x(), p.y());
        if (frame) *frame = PlaneFrame{Eigen::Vector3d(0.0, 0.0, 0.5 * (zmin + zmax)), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
    } else {
        const PlaneFit plane = bestFitPlane(pts);
        double off = 0.0;
        for (const auto& p : pts) off = std::max(off, std::abs((p - plane.centroid).dot(plane.normal)));
        if (off > flatness * size) {
            throw GeometryError("curve: not planar (a control point lies " + std::to_string(off) +
                                " from the best-fit plane, the limit is " + std::to_string(flatness * size) + ")");
        }
        // Seen from the side of +z (or along the fit's own normal when the plane is vertical), with a
        // right-handed frame (e1, e2, n): a curve that turns left seen from there keeps kappa > 0.
        const Eigen::Vector3d n = plane.normal.z() < 0.0 ? Eigen::Vector3d(-plane.normal) : plane.normal;
        const Eigen::Vector3d e1 = plane.axisU, e2 = n.cross(e1);
        for (const auto& p : pts) flat.emplace_back((p - plane.centroid).dot(e1), (p - plane.centroid).dot(e2));
        if (frame) *frame = PlaneFrame{plane.centroid, e1, e2};
    }
    return Curve2d(curve.degree(), curve.knots(), flat, curve.weights(), curve.isClosed());
}

Curve3d spaceCurve(const Curve2d& curve, const PlaneFrame& frame)
{
    std::vector<Eigen::Vector3d> pts;
    for (const auto& p : curve.points()) pts.push_back(frame.origin + p.x() * frame.e1 + p.y() * frame.e2);
    return Curve3d(curve.degree(), curve.knots(), pts, curve.weights(), curve.isClosed());
}

}  // namespace sculptline::solvers::aesthetics
