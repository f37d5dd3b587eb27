// Kernel <-> OpenCASCADE B-splines. OCCT stores knots as distinct values with multiplicities
// (Geom_BSplineCurve.hxx); a periodic OCCT curve holds one period: its knots run over
// [first, first + T] with equal end multiplicities summing (without the last) to the pole count.
#include "solvers/exchange/occt_geometry.h"

#include "solvers/exchange/exchange.h"

#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <utility>
#include <vector>

namespace sculptline::solvers::exchange {
namespace {

struct DistinctKnots {
    std::vector<double> values;
    std::vector<int> mults;
    int poleShift = 0;  ///< periodic: OCCT's first pole is the kernel's pole poleShift
};

// Runs of equal values in knots[first..last] (inclusive).
DistinctKnots runs(const KnotVector& knots, size_t first, size_t last)
{
    DistinctKnots d;
    for (size_t i = first; i <= last; ++i) {
        if (!d.values.empty() && knots[i] == d.values.back()) {
            ++d.mults.back();
        } else {
            d.values.push_back(knots[i]);
            d.mults.push_back(1);
        }
    }
    return d;
}

TColStd_Array1OfReal realArray(const std::vector<double>& v)
{
    TColStd_Array1OfReal a(1, static_cast<int>(v.size()));
    for (size_t i = 0; i < v.size(); ++i) a(static_cast<int>(i) + 1) = v[i];
    return a;
}

TColStd_Array1OfInteger intArray(const std::vector<int>& v)
{
    TColStd_Array1OfInteger a(1, static_cast<int>(v.size()));
    for (size_t i = 0; i < v.size(); ++i) a(static_cast<int>(i) + 1) = v[i];
    return a;
}

gp_Pnt pnt(const Eigen::Vector3d& p) { return gp_Pnt(p.x(), p.y(), p.z()); }

// One period of a closed curve's knots: the distinct values of [t_p, t_{n+1}] with the seam's
// multiplicity counted on both sides of t_p (t_{p-k} == t_p - T is the same knot one period back,
// and its copies just left of t_{n+1} stand for it). Sum of the multiplicities without the last
// = n + 1 - p, the number of unique poles.
DistinctKnots periodKnots(const Curve3d& c)
{
    const KnotVector& t = c.knots();
    const size_t p = static_cast<size_t>(c.degree());
    const size_t end = static_cast<size_t>(c.pointCount());  // index n + 1
    size_t right = 0;  // copies of t_p from index p on
    while (p + right < end && t[p + right] == t[p]) ++right;
    size_t left = 0;  // copies of t_{n+1} from index n+1 down (index n+1 itself is t_p's copy p)
    while (end - left > p && t[end - left] == t[end]) ++left;
    DistinctKnots d = runs(t, p + right, end - left);  // interior values, with t_{n+1} once...
    // ...the interior is everything strictly between the seam copies.
    DistinctKnots interior;
    for (size_t i = 0; i < d.values.size(); ++i) {
        if (d.values[i] == t[p] || d.values[i] == t[end]) continue;
        interior.values.push_back(d.values[i]);
        interior.mults.push_back(d.mults[i]);
    }
    const int seam = static_cast<int>(right + left) - 1;
    DistinctKnots out;
    out.values.push_back(t[p]);
    out.mults.push_back(seam);
    out.values.insert(out.values.end(), interior.values.begin(), interior.values.end());
    out.mults.insert(out.mults.end(), interior.mults.begin(), interior.mults.end());
    out.values.push_back(t[end]);
    out.mults.push_back(seam);
    // OCCT unwraps one period so that the last copy of its first knot sits at flat index `degree`
    // (BSplCLib::KnotSequence); the kernel has its first copy there. With `right` copies from t_p
    // on, OCCT's poles start `right - 1` poles later.
    out.poleShift = static_cast<int>(right) - 1;
    return out;
}

}  // namespace

Handle(Geom_BSplineCurve) toOcct(const Curve3d& curve, const std::string& field)
{
    const int p = curve.degree();
    const bool periodic = curve.isClosed();
    DistinctKnots knots = periodic ? periodKnots(curve) : runs(curve.knots(), 0, curve.knots().size() - 1);
    // A periodic OCCT curve holds the unique poles (it repeats the first `degree` itself,
    // BSplCLib::Unperiodize), rotated by the seam's copies (periodKnots).
    const int poleCount = periodic ? curve.pointCount() - p : curve.pointCount();
    TColgp_Array1OfPnt poles(1, poleCount);
    TColStd_Array1OfReal weights(1, poleCount);
    for (int i = 0; i < poleCount; ++i) {
        const int k = (i + knots.poleShift) % poleCount;
        poles(i + 1) = pnt(curve.points()[k]);
        weights(i + 1) = curve.weight(k);
    }
    try {
        if (curve.isRational()) {
            return new Geom_BSplineCurve(poles, weights, realArray(knots.values), intArray(knots.mults), p, periodic);
        }
        return new Geom_BSplineCurve(poles, realArray(knots.values), intArray(knots.mults), p, periodic);
    } catch (const Standard_Failure& e) {
        throw ExchangeError(field + ": OpenCASCADE refuses the B-spline (" + e.GetMessageString() + ")");
    }
}

Handle(Geom_BSplineSurface) toOcct(const Surface3d& s, const std::string& field)
{
    const DistinctKnots u = runs(s.knotsU(), 0, s.knotsU().size() - 1);
    const DistinctKnots v = runs(s.knotsV(), 0, s.knotsV().size() - 1);
    TColgp_Array2OfPnt poles(1, s.countU(), 1, s.countV());
    TColStd_Array2OfReal weights(1, s.countU(), 1, s.countV());
    for (int i = 0; i < s.countU(); ++i) {
        for (int j = 0; j < s.countV(); ++j) {
            poles(i + 1, j + 1) = pnt(s.point(i, j));
            weights(i + 1, j + 1) = s.weight(i, j);
        }
    }
    try {
        if (s.isRational()) {
            return new Geom_BSplineSurface(poles, weights, realArray(u.values), realArray(v.values), intArray(u.mults),
                                           intArray(v.mults), s.degreeU(), s.degreeV());
        }
        return new Geom_BSplineSurface(poles, realArray(u.values), realArray(v.values), intArray(u.mults),
                                       intArray(v.mults), s.degreeU(), s.degreeV());
    } catch (const Standard_Failure& e) {
        throw ExchangeError(field + ": OpenCASCADE refuses the B-spline (" + e.GetMessageString() + ")");
    }
}

}  // namespace sculptline::solvers::exchange
