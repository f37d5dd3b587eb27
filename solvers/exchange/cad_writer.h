#pragma once
// STEP AP214 and IGES 5.3 text of curves and surfaces with their exact B-spline geometry.
#include "solvers/exchange/exchange.h"

namespace sculptline::solvers::exchange {

/// Curves as edges (a GEOMETRIC_CURVE_SET), surfaces as faces on their natural bounds (a
/// SHELL_BASED_SURFACE_MODEL); STEPControl_Writer, schema AP214, millimetres.
std::string encodeStep(const ExchangeContent& content);

/// Curves and surfaces as free geometry (entities 126 and 128); IGESControl_Writer, millimetres.
std::string encodeIges(const ExchangeContent& content);

}  // namespace sculptline::solvers::exchange
