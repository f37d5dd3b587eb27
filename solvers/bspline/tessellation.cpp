#include "solvers/bspline/tessellation.h"

#include "solvers/bspline/basis.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace sculptline::solvers {
namespace {

/// Interior probes per segment for the chord test: at 1/4, 1/2 and 3/4. The midpoint alone misses
/// S-shaped segments whose inflection sits at the middle (the midpoint then lies on the chord).
constexpr int kChordProbes = 3;
/// Tangents and normals at a segment's end are taken this fraction of the segment inside it, so a
/// kink at a knot (multiplicity = degree) is seen from the segment's own side (findSpan picks the
/// span to the right of a knot), instead of forcing endless bisection next to the kink.
constexpr double kInsideNudge = 1e-7;
/// Refinement rounds for surfaces (U then V); each round only adds parameters, and in practice the
/// second round already changes nothing.
constexpr int kMaxSurfaceRounds = 4;
/// Floor of the relative chord tolerance's scale, so a degenerate (point-like) geometry still gets
/// a positive tolerance.
constexpr double kMinimumScale = 1e-12;

double chordToleranceFor(const TessellationTolerance& t, double controlSize)
{
    if (t.chordTolerance > 0.0) return t.chordTolerance;
    return kRelativeChordTolerance * std::max(controlSize, kMinimumScale);
}

/// Angle between two directions; 0 when either is (numerically) zero: no direction, no criterion.
double turningAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const double scale = a.norm() * b.norm();
    if (!(scale > 0.0)) return 0.0;
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// Domain start, distinct interior knots, domain end: the knot spans of the domain.
std::vector<double> spanBreaks(int degree, const KnotVector& knots, double start, double end)
{
    std::vector<double> breaks{start};
    for (double k : interiorBreakpoints(degree, knots)) breaks.push_back(k);
    breaks.push_back(end);
    return breaks;
}

/// Every span cut into `segments` equal parts; increasing, both domain ends included.
std::vector<double> initialParameters(const std::vector<double>& breaks, int segments)
{
    std::vector<double> params;
    for (size_t s = 0; s + 1 < breaks.size(); ++s) {
        for (int k = 0; k < segments; ++k) {
            params.push_back(breaks[s] + (breaks[s + 1] - breaks[s]) * k / segments);
        }
    }
    params.push_back(breaks.back());
    return params;
}

int segmentsPerSpan(const TessellationTolerance& t) { return std::max(1, t.minSegmentsPerSpan); }

class CurveRefiner {
public:
    CurveRefiner(const Curve3d& c, double chord, double angle, size_t budget)
        : curve_(c), chord_(chord), angle_(angle), budget_(budget)
    {
    }

    /// Appends a and the refinement points of (a, b) (not b) to out.
    void refine(double a, double b, int depth, Polyline& out) const
    {
        if (depth < kMaxRefinementDepth && out.points.size() < budget_ && !flat(a, b)) {
            const double m = 0.5 * (a + b);
            refine(a, m, depth + 1, out);
            refine(m, b, depth + 1, out);
            return;
        }
        out.params.push_back(a);
        out.points.push_back(curve_.evaluate(a));
    }

private:
    bool flat(double a, double b) const
    {
        const Eigen::Vector3d pa = curve_.evaluate(a);
        const Eigen::Vector3d pb = curve_.evaluate(b);
        for (int k = 1; k <= kChordProbes; ++k) {
            const double t = a + (b - a) * k / (kChordProbes + 1);
            if (distanceToSegment(curve_.evaluate(t), pa, pb) > chord_) return false;
        }
        const double h = (b - a) * kInsideNudge;
        const Eigen::Vector3d ta = curve_.derivatives(a + h, 1)[1];
        const Eigen::Vector3d tb = curve_.derivatives(b - h, 1)[1];
        return turningAngle(ta, tb) <= angle_;
    }

    const Curve3d& curve_;
    double chord_;
    double angle_;
    size_t budget_;  ///< no bisection once the polyline has this many points
};

/// Refines the parameters of one surface direction against the grid lines at the other direction's
/// parameters (the "across" list).
class SurfaceRefiner {
public:
    SurfaceRefiner(const Surface3d& s, double chord, double angle) : surface_(s), chord_(chord), angle_(angle) {}

    /// Returns true when `along` gained parameters. minWidth stops bisection (depth limit), and so
    /// does reaching `maxVertices` grid vertices.
    bool refine(Direction d, std::vector<double>& along, const std::vector<double>& across, double minWidth,
                size_t maxVertices) const
    {
        std::vector<double> out;
        // Splits allowed: the budget's share of this direction, less the parameters already there.
        const size_t maxAlong = std::max(along.size(), maxVertices / std::max<size_t>(across.size(), 1));
        size_t splits = maxAlong - along.size();
        for (size_t i = 0; i + 1 < along.size(); ++i) split(d, along[i], along[i + 1], across, minWidth, splits, out);
        out.push_back(along.back());
        const bool changed = out.size() != along.size();
        along = std::move(out);
        return changed;
    }

private:
    Eigen::Vector3d point(Direction d, double t, double c) const
    {
        return d == Direction::U ? surface_.evaluate(t, c) : surface_.evaluate(c, t);
    }
    Eigen::Vector3d normal(Direction d, double t, double c) const
    {
        return d == Direction::U ? surface_.normal(t, c) : surface_.normal(c, t);
    }

    void split(Direction d, double a, double b, const std::vector<double>& across, double minWidth, size_t& splits,
               std::vector<double>& out) const
    {
        if (splits > 0 && b - a > 2.0 * minWidth && !flat(d, a, b, across)) {
            --splits;
            const double m = 0.5 * (a + b);
            split(d, a, m, across, minWidth, splits, out);
            split(d, m, b, across, minWidth, splits, out);
            return;
        }
        out.push_back(a);
    }

    bool flat(Direction d, double a, double b, const std::vector<double>& across) const
    {
        const double h = (b - a) * kInsideNudge;
        for (double c : across) {
            const Eigen::Vector3d pa = point(d, a, c);
            const Eigen::Vector3d pb = point(d, b, c);
            for (int k = 1; k <= kChordProbes; ++k) {
                const double t = a + (b - a) * k / (kChordProbes + 1);
                if (distanceToSegment(point(d, t, c), pa, pb) > chord_) return false;
            }
            if (turningAngle(normal(d, a + h, c), normal(d, b - h, c)) > angle_) return false;
        }
        return true;
    }

    const Surface3d& surface_;
    double chord_;
    double angle_;
};

/// Control-net bounding-box diagonal of a surface (Surface3d has no controlSize()).
double controlSize(const Surface3d& s)
{
    Eigen::Vector3d lo = s.points().front();
    Eigen::Vector3d hi = lo;
    for (const auto& p : s.points()) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return (hi - lo).norm();
}

/// Smallest gap of an increasing list.
double smallestGap(const std::vector<double>& p)
{
    double gap = p.back() - p.front();
    for (size_t i = 0; i + 1 < p.size(); ++i) gap = std::min(gap, p[i + 1] - p[i]);
    return gap;
}

/// Values and first derivatives of the degree+1 basis functions at each parameter (A2.3 once per
/// grid line, not once per vertex).
std::vector<GridBasis::Line> lineBases(int degree, const KnotVector& knots, const std::vector<double>& params)
{
    std::vector<GridBasis::Line> out;
    out.reserve(params.size());
    for (double t : params) {
        const int span = findSpan(degree, knots, t);
        out.push_back({span, basisDerivatives(span, t, degree, 1, knots)});
    }
    return out;
}

/// Below this |Su x Sv| / (|Su||Sv|) (or a first derivative this small relative to the other) the
/// grid's normal is left to Surface::normal(), which takes the limit at collapsed edges; above it
/// both compute the same normalized cross product. Far above round-off, far below any real angle.
constexpr double kFastNormalGuard = 1e-9;

/// Points and normals of `mesh`'s grid by tensor contraction (The NURBS Book A3.5/A4.4 with the
/// basis of each row and column computed once): per row the control net is contracted over u, then
/// per vertex over v, in homogeneous coordinates; rational derivatives by A4.4's quotient rule.
void evaluateGrid(const Surface3d& surface, const std::vector<GridBasis::Line>& bu, const std::vector<GridBasis::Line>& bv,
                  const std::vector<double>& us, const std::vector<double>& vs, std::vector<Eigen::Vector3d>& vertices,
                  std::vector<Eigen::Vector3d>& normals)
{
    const int p = surface.degreeU(), q = surface.degreeV();
    const int countV = surface.countV();
    const bool rational = surface.isRational();
    vertices.clear();
    normals.clear();
    vertices.reserve(bu.size() * bv.size());
    normals.reserve(bu.size() * bv.size());
    std::vector<Eigen::Vector4d> net(surface.points().size());
    for (size_t k = 0; k < net.size(); ++k) {
        const double w = rational ? surface.weights()[k] : 1.0;
        net[k] << w * surface.points()[k], w;
    }
    std::vector<Eigen::Vector4d> row(static_cast<size_t>(countV)), rowU(static_cast<size_t>(countV));
    for (size_t r = 0; r < bu.size(); ++r) {
        const GridBasis::Line& a = bu[r];
        for (int j = 0; j < countV; ++j) {
            Eigen::Vector4d s = Eigen::Vector4d::Zero(), su = Eigen::Vector4d::Zero();
            for (int k = 0; k <= p; ++k) {
                const Eigen::Vector4d& x = net[static_cast<size_t>(a.span - p + k) * countV + j];
                s += a.d(0, k) * x;
                su += a.d(1, k) * x;
            }
            row[j] = s;
            rowU[j] = su;
        }
        for (size_t c = 0; c < bv.size(); ++c) {
            const GridBasis::Line& b = bv[c];
            Eigen::Vector4d s = Eigen::Vector4d::Zero(), su = Eigen::Vector4d::Zero(), sv = Eigen::Vector4d::Zero();
            for (int l = 0; l <= q; ++l) {
                const size_t j = static_cast<size_t>(b.span - q + l);
                s += b.d(0, l) * row[j];
                su += b.d(0, l) * rowU[j];
                sv += b.d(1, l) * row[j];
            }
            const Eigen::Vector3d x = s.head<3>() / s.w();
            const Eigen::Vector3d du = (su.head<3>() - su.w() * x) / s.w();
            const Eigen::Vector3d dv = (sv.head<3>() - sv.w() * x) / s.w();
            const Eigen::Vector3d n = du.cross(dv);
            const double lu = du.norm(), lv = dv.norm();
            const bool regular = lu > kFastNormalGuard * lv && lv > kFastNormalGuard * lu && n.norm() > kFastNormalGuard * lu * lv;
            vertices.push_back(x);
            normals.push_back(regular ? Eigen::Vector3d(n.normalized()) : surface.normal(us[r], vs[c]));
        }
    }
}

/// Where the kernel defines no normal (a point with no tangent plane at all), the average of the
/// adjacent faces (two triangles per cell, (p00, p10, p11) and (p00, p11, p01), face normal ~ Su x
/// Sv) is what shading needs; left zero only if the faces are degenerate too.
void fillUndefinedNormals(int rows, int cols, const std::vector<Eigen::Vector3d>& vertices, std::vector<Eigen::Vector3d>& normals)
{
    if (std::none_of(normals.begin(), normals.end(), [](const Eigen::Vector3d& n) { return n.squaredNorm() == 0.0; })) return;
    std::vector<Eigen::Vector3d> faceSum(vertices.size(), Eigen::Vector3d::Zero());
    for (int r = 0; r + 1 < rows; ++r) {
        for (int c = 0; c + 1 < cols; ++c) {
            const int i00 = r * cols + c, i10 = (r + 1) * cols + c, i11 = i10 + 1, i01 = i00 + 1;
            for (const Eigen::Vector3i& t : {Eigen::Vector3i(i00, i10, i11), Eigen::Vector3i(i00, i11, i01)}) {
                const Eigen::Vector3d n = (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
                for (int k = 0; k < 3; ++k) faceSum[t[k]] += n;
            }
        }
    }
    for (size_t i = 0; i < normals.size(); ++i) {
        if (normals[i].squaredNorm() == 0.0 && faceSum[i].squaredNorm() > 0.0) normals[i] = faceSum[i].normalized();
    }
}

}  // namespace

GridBasis::GridBasis(const Surface3d& surface, std::vector<double> u, std::vector<double> v)
    : degreeU_(surface.degreeU()), degreeV_(surface.degreeV()), countU_(surface.countU()), countV_(surface.countV()),
      knotsU_(surface.knotsU()), knotsV_(surface.knotsV()), u_(std::move(u)), v_(std::move(v)),
      bu_(lineBases(degreeU_, knotsU_, u_)), bv_(lineBases(degreeV_, knotsV_, v_))
{
}

bool GridBasis::fits(const Surface3d& surface) const
{
    return surface.degreeU() == degreeU_ && surface.degreeV() == degreeV_ && surface.countU() == countU_ &&
           surface.countV() == countV_ && surface.knotsU() == knotsU_ && surface.knotsV() == knotsV_;
}

void GridBasis::evaluate(const Surface3d& surface, std::vector<Eigen::Vector3d>& vertices,
                         std::vector<Eigen::Vector3d>& normals) const
{
    evaluateGrid(surface, bu_, bv_, u_, v_, vertices, normals);
    fillUndefinedNormals(static_cast<int>(u_.size()), static_cast<int>(v_.size()), vertices, normals);
}

double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const Eigen::Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    if (!(len2 > 0.0)) return (p - a).norm();
    const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
    return (p - (a + t * ab)).norm();
}

Polyline tessellate(const Curve3d& curve, const TessellationTolerance& tolerance)
{
    const auto breaks = spanBreaks(curve.degree(), curve.knots(), curve.domainStart(), curve.domainEnd());
    const auto params = initialParameters(breaks, segmentsPerSpan(tolerance));
    const CurveRefiner refiner(curve, chordToleranceFor(tolerance, curve.controlSize()), tolerance.maxTurningAngle,
                               static_cast<size_t>(std::max(tolerance.maxVertices, 0)));
    Polyline out;
    for (size_t i = 0; i + 1 < params.size(); ++i) refiner.refine(params[i], params[i + 1], 0, out);
    out.params.push_back(params.back());
    out.points.push_back(curve.evaluate(params.back()));
    return out;
}

GridMesh tessellate(const Surface3d& surface, const TessellationTolerance& tolerance)
{
    const SurfaceRefiner refiner(surface, chordToleranceFor(tolerance, controlSize(surface)),
                                 tolerance.maxTurningAngle);
    GridMesh mesh;
    mesh.u = initialParameters(spanBreaks(surface.degreeU(), surface.knotsU(), surface.domainStart(Direction::U),
                                          surface.domainEnd(Direction::U)),
                               segmentsPerSpan(tolerance));
    mesh.v = initialParameters(spanBreaks(surface.degreeV(), surface.knotsV(), surface.domainStart(Direction::V),
                                          surface.domainEnd(Direction::V)),
                               segmentsPerSpan(tolerance));
    const double depthScale = std::ldexp(1.0, -kMaxRefinementDepth);
    const double minWidthU = smallestGap(mesh.u) * depthScale;
    const double minWidthV = smallestGap(mesh.v) * depthScale;
    const size_t budget = static_cast<size_t>(std::max(tolerance.maxVertices, 0));
    for (int round = 0; round < kMaxSurfaceRounds; ++round) {
        const bool changedU = refiner.refine(Direction::U, mesh.u, mesh.v, minWidthU, budget);
        const bool changedV = refiner.refine(Direction::V, mesh.v, mesh.u, minWidthV, budget);
        if (!changedU && !changedV) break;
    }
    return meshOnGrid(surface, std::move(mesh.u), std::move(mesh.v));
}

GridMesh meshOnGrid(const Surface3d& surface, std::vector<double> u, std::vector<double> v)
{
    const GridBasis basis(surface, std::move(u), std::move(v));
    GridMesh mesh;
    mesh.u = basis.u();
    mesh.v = basis.v();
    const int rows = mesh.rows();
    const int cols = mesh.cols();
    basis.evaluate(surface, mesh.vertices, mesh.normals);
    // Two triangles per cell; (p00, p10, p11) has face normal ~ Su x Sv, the kernel's normal side.
    mesh.triangles.reserve(2 * static_cast<size_t>(std::max(rows - 1, 0)) * static_cast<size_t>(std::max(cols - 1, 0)));
    for (int r = 0; r + 1 < rows; ++r) {
        for (int c = 0; c + 1 < cols; ++c) {
            const int i00 = r * cols + c, i10 = (r + 1) * cols + c, i11 = i10 + 1, i01 = i00 + 1;
            mesh.triangles.emplace_back(i00, i10, i11);
            mesh.triangles.emplace_back(i00, i11, i01);
        }
    }
    return mesh;
}

}  // namespace sculptline::solvers
