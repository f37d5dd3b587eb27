#include "solvers/surfaces/compatible_curves.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/knot_algorithms.h"

#include <algorithm>
#include <map>
#include <string>

namespace sculptline::solvers::surfaces {

Curve3d normalizedCurve(const Curve3d& curve)
{
    const Curve3d c = curve.clamped();
    const double a = c.domainStart();
    const double b = c.domainEnd();
    KnotVector knots = c.knots();
    for (double& k : knots) k = (k - a) / (b - a);
    // Exact ends: the affine map of a and b can be off by an ulp.
    const int p = c.degree();
    for (int i = 0; i <= p; ++i) {
        knots[i] = 0.0;
        knots[knots.size() - 1 - i] = 1.0;
    }
    return Curve3d::fromHomogeneous(p, std::move(knots), c.homogeneous(), c.isRational());
}

namespace {

// Interior knot values of a normalized curve with their multiplicities.
std::map<double, int> interiorMultiplicities(const KnotVector& knots, int degree)
{
    std::map<double, int> m;
    for (size_t i = degree + 1; i + degree + 1 < knots.size(); ++i) ++m[knots[i]];
    return m;
}

}  // namespace

CurveLayout commonLayout(const std::vector<Curve3d>& normalized, int minDegree)
{
    CurveLayout layout;
    layout.degree = minDegree;
    for (const Curve3d& c : normalized) layout.degree = std::max(layout.degree, c.degree());
    std::map<double, int> merged;
    for (const Curve3d& c : normalized) {
        // Elevation by t raises every interior multiplicity by t (A5.9 keeps the continuity C^{p-m}).
        const int t = layout.degree - c.degree();
        for (const auto& [value, mult] : interiorMultiplicities(c.knots(), c.degree()))
            merged[value] = std::max(merged[value], std::min(mult + t, layout.degree));
    }
    layout.knots.assign(layout.degree + 1, 0.0);
    for (const auto& [value, mult] : merged) layout.knots.insert(layout.knots.end(), mult, value);
    layout.knots.insert(layout.knots.end(), layout.degree + 1, 1.0);
    return layout;
}

std::optional<Curve3d> conformToLayout(const Curve3d& normalized, const CurveLayout& layout)
{
    if (normalized.degree() > layout.degree) return std::nullopt;
    const bool rational = normalized.isRational();
    KnotVector knots = normalized.knots();
    ControlMatrix rows = normalized.homogeneous();
    if (normalized.degree() < layout.degree) {
        KnotsAndPoints e = elevateDegree(normalized.degree(), knots, rows, layout.degree - normalized.degree());
        knots = std::move(e.knots);
        rows = std::move(e.points);
    }
    // Multiset difference layout.knots - knots; both sorted.
    std::vector<double> missing;
    size_t a = 0;
    size_t b = 0;
    while (a < layout.knots.size()) {
        if (b < knots.size() && knots[b] == layout.knots[a]) {
            ++a;
            ++b;
        } else if (b < knots.size() && knots[b] < layout.knots[a]) {
            return std::nullopt;  // the curve has a knot the layout lacks
        } else {
            missing.push_back(layout.knots[a++]);
        }
    }
    if (b != knots.size()) return std::nullopt;
    if (!missing.empty()) {
        KnotsAndPoints r = refineKnots(layout.degree, knots, rows, missing);
        knots = std::move(r.knots);
        rows = std::move(r.points);
    }
    return Curve3d::fromHomogeneous(layout.degree, std::move(knots), rows, rational);
}

bool anyRational(const std::vector<Curve3d>& curves)
{
    return std::any_of(curves.begin(), curves.end(), [](const Curve3d& c) { return c.isRational(); });
}

ControlMatrix controlRows(const Curve3d& curve, bool rational)
{
    if (curve.isRational() || !rational) return curve.homogeneous();
    ControlMatrix rows(curve.pointCount(), 4);
    for (int i = 0; i < curve.pointCount(); ++i) rows.row(i) << curve.points()[i].transpose(), 1.0;
    return rows;
}

std::vector<Curve3d> makeCompatible(const std::vector<Curve3d>& curves, int minDegree)
{
    if (curves.empty()) throw GeometryError("curves: empty, at least one curve is needed");
    std::vector<Curve3d> normalized;
    normalized.reserve(curves.size());
    for (const Curve3d& c : curves) normalized.push_back(normalizedCurve(c));
    const CurveLayout layout = commonLayout(normalized, minDegree);
    const bool rational = anyRational(normalized);
    std::vector<Curve3d> out;
    out.reserve(curves.size());
    for (size_t k = 0; k < normalized.size(); ++k) {
        // commonLayout contains every knot of a valid curve (interior multiplicity at most its
        // degree, basis.h's validateKnots); never dereference an empty result regardless.
        std::optional<Curve3d> fitted = conformToLayout(normalized[k], layout);
        if (!fitted)
            throw GeometryError("curves[" + std::to_string(k) + "]: its knots do not fit the common knot vector");
        Curve3d conformed = std::move(*fitted);
        if (rational && !conformed.isRational())
            conformed = Curve3d::fromHomogeneous(layout.degree, conformed.knots(), controlRows(conformed, true), true);
        out.push_back(std::move(conformed));
    }
    return out;
}

Curve3d reversedCurve(const Curve3d& normalized)
{
    KnotVector knots(normalized.knots().rbegin(), normalized.knots().rend());
    for (double& k : knots) k = 1.0 - k;
    const ControlMatrix rows = normalized.homogeneous().colwise().reverse();
    return Curve3d::fromHomogeneous(normalized.degree(), std::move(knots), rows, normalized.isRational());
}

}  // namespace sculptline::solvers::surfaces
