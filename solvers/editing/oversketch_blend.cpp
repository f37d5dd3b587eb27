#include "solvers/editing/oversketch.h"

#include "solvers/bspline/geometry_error.h"

namespace sculptline::solvers::editing::detail {

template <int Dim>
BSplineCurve<Dim> oversketchBlend(const BSplineCurve<Dim>&, const StrokeOnCurve<Dim>&, const OversketchOptions&,
                                  std::pair<double, double>&, double&)
{
    throw GeometryError("method: blend is not implemented yet");
}

template BSplineCurve<2> oversketchBlend<2>(const BSplineCurve<2>&, const StrokeOnCurve<2>&, const OversketchOptions&,
                                            std::pair<double, double>&, double&);
template BSplineCurve<3> oversketchBlend<3>(const BSplineCurve<3>&, const StrokeOnCurve<3>&, const OversketchOptions&,
                                            std::pair<double, double>&, double&);

}  // namespace sculptline::solvers::editing::detail
