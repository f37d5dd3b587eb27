#include "solvers/incidence/composition.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/knot_algorithms.h"
#include "solvers/incidence/bernstein.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace sculptline::solvers::incidence {

namespace {

// Breakpoints closer than this (relative to G's domain length) are one: far below anything a
// designer or a solver distinguishes, far above the root finder's resolution (1e-10 of a span).
constexpr double kMergeRelative = 1e-9;
// How far G may leave F's domain (relative to the domain's size) before it is refused.
constexpr double kDomainSlackRelative = 1e-12;
// A coefficient within this (relative to the knot range) of a knot value counts as on the line.
constexpr double kOnLineRelative = 1e-13;
// Entries of A below this are round-off of zero (a basis function vanishing on a cell's edge that
// G runs along or touches): dropped, so that a control point the curve does not depend on has an
// empty column. A's rows are partitions of unity, so this is relative; dropping a true entry this
// small moves H by less than its round-off.
constexpr double kNegligible = 1e-15;

Curve2d openForm(const Curve2d& g)
{
    if (g.isRational()) throw GeometryError("domain curve: must be non-rational (a polynomial B-spline)");
    return g.isClosed() ? g.clamped() : g;
}

ControlMatrix rowsOf(const Curve2d& g)
{
    ControlMatrix rows(g.pointCount(), 2);
    for (int i = 0; i < g.pointCount(); ++i) rows.row(i) = g.points()[i].transpose();
    return rows;
}

// The distinct knot values bounding G's non-empty spans inside its domain.
std::vector<double> spanBounds(const Curve2d& g)
{
    std::vector<double> bounds{g.domainStart()};
    for (double t : interiorBreakpoints(g.degree(), g.knots())) bounds.push_back(t);
    bounds.push_back(g.domainEnd());
    return bounds;
}

void checkInsideDomain(const SurfaceStructure& f, const Curve2d& g)
{
    const double u0 = f.knotsU[f.degreeU], u1 = f.knotsU[f.countU];
    const double v0 = f.knotsV[f.degreeV], v1 = f.knotsV[f.countV];
    const double slackU = kDomainSlackRelative * (u1 - u0), slackV = kDomainSlackRelative * (v1 - v0);
    const std::vector<double> bounds = spanBounds(g);
    constexpr int kSamplesPerSpan = 16;
    for (size_t s = 0; s + 1 < bounds.size(); ++s) {
        for (int k = 0; k <= kSamplesPerSpan; ++k) {
            const double t = bounds[s] + (bounds[s + 1] - bounds[s]) * k / kSamplesPerSpan;
            const Eigen::Vector2d uv = g.evaluate(t);
            if (uv.x() < u0 - slackU || uv.x() > u1 + slackU || uv.y() < v0 - slackV || uv.y() > v1 + slackV) {
                throw GeometryError("domain curve: leaves the surface's parameter domain at t = " + std::to_string(t));
            }
        }
    }
}

struct Candidate {
    double t;
    int priority;  // 2: a knot of G, 1: an extra breakpoint, 0: a knot-line crossing
};

// The parameters in (a, b) of G's span where coordinate `axis` equals an interior knot of F.
void spanCrossings(const Eigen::VectorXd& coefficients, const std::vector<double>& lines, double range, double a,
                   double b, std::vector<double>& out)
{
    const double tol = kOnLineRelative * range;
    for (double line : lines) {
        if (line < coefficients.minCoeff() - tol || line > coefficients.maxCoeff() + tol) continue;
        const Eigen::VectorXd shifted = coefficients.array() - line;
        for (double s : bernsteinRoots(shifted, tol)) out.push_back(a + (b - a) * s);
    }
}

// The Bezier extraction of span `span` of a degree-p basis: (p+1) x (p+1), rows the Bezier points
// on [knots[span], knots[span+1]], columns the basis functions span-p .. span.
Eigen::MatrixXd spanExtraction(int p, const KnotVector& knots, int count, int span)
{
    const ControlMatrix identity = ControlMatrix::Identity(count, count);
    const KnotsAndPoints piece = extractSegment(p, knots, identity, knots[span], knots[span + 1]);
    return piece.points.middleCols(span - p, p + 1);
}

// The p+1 polynomials C(p,k) x^k (1-x)^(p-k) of degree p r, x given by its r+1 Bernstein coefficients.
std::vector<Eigen::VectorXd> bernsteinOfPolynomial(int p, const Eigen::VectorXd& x)
{
    const Eigen::VectorXd one = Eigen::VectorXd::Ones(x.size());
    const Eigen::VectorXd y = one - x;  // 1 - x: the basis is a partition of unity
    std::vector<Eigen::VectorXd> xPower{Eigen::VectorXd::Ones(1)}, yPower{Eigen::VectorXd::Ones(1)};
    for (int k = 1; k <= p; ++k) {
        xPower.push_back(bernsteinProduct(xPower.back(), x));
        yPower.push_back(bernsteinProduct(yPower.back(), y));
    }
    std::vector<Eigen::VectorXd> out;
    for (int k = 0; k <= p; ++k) out.push_back(binomial(p, k) * bernsteinProduct(xPower[k], yPower[p - k]));
    return out;
}

}  // namespace

SurfaceStructure SurfaceStructure::of(const Surface3d& surface)
{
    if (surface.isRational()) throw GeometryError("surface: curve incidence needs a non-rational surface");
    return {surface.degreeU(), surface.degreeV(), surface.knotsU(), surface.knotsV(), surface.countU(), surface.countV()};
}

CompositionSpace compositionSpace(const SurfaceStructure& f, const Curve2d& domainCurve,
                                  const std::vector<double>& extraBreakpoints)
{
    const Curve2d g = openForm(domainCurve);
    const int r = g.degree();
    if ((f.degreeU + f.degreeV) * r > kMaxDegree) {
        throw GeometryError("domain curve: the surface curve's degree (" + std::to_string((f.degreeU + f.degreeV) * r) +
                            ") exceeds the kernel's maximum " + std::to_string(kMaxDegree));
    }
    checkInsideDomain(f, g);
    const double t0 = g.domainStart(), t1 = g.domainEnd();
    const std::vector<double> linesU = interiorBreakpoints(f.degreeU, f.knotsU);
    const std::vector<double> linesV = interiorBreakpoints(f.degreeV, f.knotsV);
    const double rangeU = f.knotsU[f.countU] - f.knotsU[f.degreeU];
    const double rangeV = f.knotsV[f.countV] - f.knotsV[f.degreeV];

    std::vector<Candidate> candidates;
    std::vector<double> crossings;
    const std::vector<double> bounds = spanBounds(g);
    const ControlMatrix rows = rowsOf(g);
    for (size_t s = 0; s + 1 < bounds.size(); ++s) {
        const KnotsAndPoints piece = extractSegment(r, g.knots(), rows, bounds[s], bounds[s + 1]);
        spanCrossings(piece.points.col(0), linesU, rangeU, bounds[s], bounds[s + 1], crossings);
        spanCrossings(piece.points.col(1), linesV, rangeV, bounds[s], bounds[s + 1], crossings);
        if (s > 0) candidates.push_back({bounds[s], 2});
    }
    for (double t : extraBreakpoints) candidates.push_back({t, 1});
    for (double t : crossings) candidates.push_back({t, 0});
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.t < b.t; });

    const double merge = kMergeRelative * (t1 - t0);
    CompositionSpace space;
    space.degree = (f.degreeU + f.degreeV) * r;
    for (size_t i = 0; i < candidates.size();) {
        // One group of values within `merge` of its first; the highest priority names it.
        size_t j = i;
        Candidate best = candidates[i];
        bool crossing = false;
        while (j < candidates.size() && candidates[j].t - candidates[i].t <= merge) {
            if (candidates[j].priority > best.priority) best = candidates[j];
            crossing = crossing || candidates[j].priority == 0;
            ++j;
        }
        i = j;
        if (best.t <= t0 + merge || best.t >= t1 - merge) continue;
        space.breakpoints.push_back(best.t);
        if (crossing) space.crossings.push_back(best.t);
    }
    const int d = space.degree;
    space.knots.assign(d + 1, t0);
    for (double t : space.breakpoints) space.knots.insert(space.knots.end(), d, t);
    space.knots.insert(space.knots.end(), d + 1, t1);
    return space;
}

Composition compose(const SurfaceStructure& f, const Curve2d& domainCurve, const std::vector<double>& extraBreakpoints)
{
    Composition out;
    out.space = compositionSpace(f, domainCurve, extraBreakpoints);
    const Curve2d g = openForm(domainCurve);
    const ControlMatrix gRows = rowsOf(g);
    const int p = f.degreeU, q = f.degreeV, r = g.degree(), d = out.space.degree;
    const int localCount = (p + 1) * (q + 1);

    std::map<int, Eigen::MatrixXd> extractionU, extractionV;
    auto extraction = [](std::map<int, Eigen::MatrixXd>& cache, int deg, const KnotVector& knots, int count,
                         int span) -> const Eigen::MatrixXd& {
        auto it = cache.find(span);
        if (it == cache.end()) it = cache.emplace(span, spanExtraction(deg, knots, count, span)).first;
        return it->second;
    };

    std::vector<double> ends{out.space.start()};
    ends.insert(ends.end(), out.space.breakpoints.begin(), out.space.breakpoints.end());
    ends.push_back(out.space.end());
    const int pieces = static_cast<int>(ends.size()) - 1;

    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(static_cast<size_t>(pieces) * (d + 1) * localCount);
    for (int k = 0; k < pieces; ++k) {
        const double a = ends[k], b = ends[k + 1];
        // The cell of F holding this piece (found at its middle: its ends may sit on knot lines).
        const Eigen::Vector2d middle = g.evaluate(0.5 * (a + b));
        const int su = findSpan(p, f.knotsU, middle.x());
        const int sv = findSpan(q, f.knotsV, middle.y());
        const Eigen::MatrixXd& eu = extraction(extractionU, p, f.knotsU, f.countU, su);
        const Eigen::MatrixXd& ev = extraction(extractionV, q, f.knotsV, f.countV, sv);

        // G's piece in Bernstein form, mapped to the cell's local coordinates in [0, 1].
        const ControlMatrix gPiece = extractSegment(r, g.knots(), gRows, a, b).points;
        const Eigen::VectorXd x = (gPiece.col(0).array() - f.knotsU[su]) / (f.knotsU[su + 1] - f.knotsU[su]);
        const Eigen::VectorXd y = (gPiece.col(1).array() - f.knotsV[sv]) / (f.knotsV[sv + 1] - f.knotsV[sv]);
        const std::vector<Eigen::VectorXd> bu = bernsteinOfPolynomial(p, x);
        const std::vector<Eigen::VectorXd> bv = bernsteinOfPolynomial(q, y);

        // M: H's Bezier points from the patch's Bezier points b_kl (column k (q+1) + l).
        Eigen::MatrixXd m(d + 1, localCount);
        for (int i = 0; i <= p; ++i)
            for (int j = 0; j <= q; ++j) m.col(i * (q + 1) + j) = bernsteinProduct(bu[i], bv[j]);
        // The patch's Bezier points from F's local control points: the tensor product eu (x) ev.
        Eigen::MatrixXd patch(localCount, localCount);
        for (int i = 0; i <= p; ++i)
            for (int j = 0; j <= q; ++j)
                for (int ia = 0; ia <= p; ++ia)
                    for (int jb = 0; jb <= q; ++jb)
                        patch(i * (q + 1) + j, ia * (q + 1) + jb) = eu(i, ia) * ev(j, jb);
        const Eigen::MatrixXd local = m * patch;

        for (int row = 0; row <= d; ++row) {
            // The point shared with a neighbouring piece is the mean of the two (equal up to round-off).
            const bool shared = (row == 0 && k > 0) || (row == d && k + 1 < pieces);
            const double w = shared ? 0.5 : 1.0;
            for (int ia = 0; ia <= p; ++ia)
                for (int jb = 0; jb <= q; ++jb) {
                    const double value = local(row, ia * (q + 1) + jb);
                    if (std::abs(value) <= kNegligible) continue;
                    triplets.emplace_back(k * d + row, (su - p + ia) * f.countV + (sv - q + jb), w * value);
                }
        }
    }
    out.matrix.resize(out.space.pointCount(), f.columnCount());
    out.matrix.setFromTriplets(triplets.begin(), triplets.end());
    return out;
}

Composition reduceMultiplicities(const Composition& full, const SurfaceStructure& f, const Curve2d& domainCurve)
{
    const Curve2d g = openForm(domainCurve);
    const int r = g.degree(), d = full.space.degree;
    const double rangeU = f.knotsU[f.countU] - f.knotsU[f.degreeU];
    const double rangeV = f.knotsV[f.countV] - f.knotsV[f.degreeV];
    const std::vector<double> knotsG = interiorBreakpoints(r, g.knots());
    const std::vector<double> linesU = interiorBreakpoints(f.degreeU, f.knotsU);
    const std::vector<double> linesV = interiorBreakpoints(f.degreeV, f.knotsV);
    // The continuity of F across the lines through `value` (its knots within 1e-9 of the range).
    auto lineContinuity = [](double value, const std::vector<double>& lines, const KnotVector& knots, int degree,
                             double range, int& k) {
        for (double line : lines)
            if (std::abs(value - line) <= 1e-9 * range) k = std::min(k, degree - knotMultiplicity(knots, line));
    };
    Composition out;
    out.space = full.space;
    ControlMatrix a = Eigen::MatrixXd(full.matrix);
    for (double t : full.space.breakpoints) {
        int k = d;  // H's continuity at t: as smooth as G and F are there
        bool justified = false;
        if (std::binary_search(knotsG.begin(), knotsG.end(), t)) {
            k = std::min(k, r - knotMultiplicity(g.knots(), t));
            justified = true;
        }
        if (std::binary_search(full.space.crossings.begin(), full.space.crossings.end(), t)) {
            const Eigen::Vector2d uv = g.evaluate(t);
            lineContinuity(uv.x(), linesU, f.knotsU, f.degreeU, rangeU, k);
            lineContinuity(uv.y(), linesV, f.knotsV, f.degreeV, rangeV, k);
            justified = true;
        }
        if (!justified || k <= 0) continue;
        constexpr double kRemovalTolerance = 1e-10;  // A's entries are weights of size about 1
        removeKnot(d, out.space.knots, a, t, std::min(k, d - 1), kRemovalTolerance, 1);
    }
    out.matrix = a.sparseView(kNegligible, 1.0);
    return out;
}

ControlMatrix surfacePointRows(const Surface3d& surface)
{
    ControlMatrix rows(surface.points().size(), 3);
    for (size_t i = 0; i < surface.points().size(); ++i) rows.row(static_cast<Eigen::Index>(i)) = surface.points()[i].transpose();
    return rows;
}

Curve3d applyComposition(const Composition& composition, const Surface3d& surface)
{
    const ControlMatrix h = composition.matrix * surfacePointRows(surface);
    std::vector<Curve3d::Point> points(static_cast<size_t>(h.rows()));
    for (Eigen::Index i = 0; i < h.rows(); ++i) points[static_cast<size_t>(i)] = h.row(i).transpose();
    return Curve3d(composition.space.degree, composition.space.knots, std::move(points));
}

}  // namespace sculptline::solvers::incidence
