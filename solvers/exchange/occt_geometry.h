#pragma once
// Kernel B-splines as OpenCASCADE geometry, exactly: the same degree, poles, weights and knots
// (distinct values with multiplicities, as Geom_BSplineCurve/Surface take them). Only this target
// and the tests that read files back include it: OCCT's headers stay away from Qt code.
#include "solvers/bspline/bspline_surface.h"

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

namespace sculptline::solvers::exchange {

/// A closed kernel curve (unwrapped convention, bspline_curve.h) becomes a periodic OCCT curve on
/// the unique poles and one period of knots; an open one (clamped or not) a non-periodic curve on
/// all its poles and knots. The parameterization is the kernel's: D0(u) == evaluate(u).
/// @throws ExchangeError when OpenCASCADE refuses the knots (it allows interior multiplicities up
///         to the degree only).
Handle(Geom_BSplineCurve) toOcct(const Curve3d& curve, const std::string& field = "curve");

/// A non-periodic OCCT surface with the kernel's poles (i along U, j along V), weights and knots.
Handle(Geom_BSplineSurface) toOcct(const Surface3d& surface, const std::string& field = "surface");

}  // namespace sculptline::solvers::exchange
