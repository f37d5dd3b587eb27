#include "solvers/surfaces/surface_modes.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/boundary_rotation.h"
#include "solvers/surfaces/coons_fill.h"
#include "solvers/surfaces/extrude.h"
#include "solvers/surfaces/loft.h"
#include "solvers/surfaces/rail_rotation.h"
#include "solvers/surfaces/revolve.h"
#include "solvers/surfaces/sweep.h"

#include <array>
#include <cmath>
#include <string>
#include <stdexcept>
#include <utility>

namespace sculptline::solvers::surfaces {
namespace {

constexpr std::array<std::pair<SurfaceMode, const char*>, 7> kNames{{{SurfaceMode::Fill, "fill"},
                                                                     {SurfaceMode::Revolve, "revolve"},
                                                                     {SurfaceMode::Extrude, "extrude"},
                                                                     {SurfaceMode::Sweep, "sweep"},
                                                                     {SurfaceMode::Loft, "loft"},
                                                                     {SurfaceMode::BoundaryRotation, "boundary-rotation"},
                                                                     {SurfaceMode::RailRotation, "rail-rotation"}}};

void requireCount(size_t count, size_t lo, size_t hi, const char* what)
{
    if (count < lo || count > hi)
        throw std::invalid_argument(std::string("curves: mode needs ") + what + ", got " + std::to_string(count) + " curves");
}

SurfaceBuild approximated(const ApproximatedSurface& r) { return {r.surface, r.maxDeviation, r.tolerance}; }

FillOptions fillOptions(const SurfaceOptions& o)
{
    FillOptions fo;
    fo.meetTolerance = o.tolerance;
    fo.tangents = o.fillTangents;
    fo.angleToleranceDegrees = o.fillAngleToleranceDegrees;
    return fo;
}

SurfaceBuild fillBuild(const FillBuilder& b, const SurfaceOptions& o)
{
    SurfaceBuild out{b.surface()};
    if (!o.fillTangents.empty()) out.maxTangentAngleDegrees = b.maxTangentAngleDegrees();
    return out;
}

LoftOptions loftOptions(const SurfaceOptions& o)
{
    LoftOptions lo;
    lo.crossDegree = o.loftDegree;
    return lo;
}

// The sweep names its path "path"; in the modes' curve list the path is curves[1].
template <class F>
auto renamingPath(F&& f) -> decltype(f())
{
    try {
        return f();
    } catch (const GeometryError& e) {
        const std::string m = e.what();
        throw GeometryError(m.rfind("path:", 0) == 0 ? "curves[1] (path):" + m.substr(5) : m);
    }
}

SurfaceBuild sweepBuild(const SweepResult& r) { return {r.surface, r.maxDeviation, r.tolerance}; }

SurfaceBuild buildUnchecked(SurfaceMode mode, const std::vector<Curve3d>& c, const SurfaceOptions& o);

// Samples at which two boundaries are compared for coincidence (evenly spaced in parameter): two
// curves a person drew as different sides differ at most of them by far more than the meet
// tolerance; a side that only partly retraces another is left to the fill's own loop checks.
constexpr int kBoundarySamples = 16;

void requireFinite(bool finite, const char* field)
{
    if (!finite) throw GeometryError(std::string(field) + ": not a finite number");
}

void requireNotCollapsed(const std::vector<Curve3d>& curves, const std::string& family)
{
    for (size_t k = 0; k < curves.size(); ++k)
        if (curves[k].isCollapsed())
            throw GeometryError(family + "[" + std::to_string(k) + "]: degenerate, all control points coincide");
}

// Two boundaries that are the same curve, in either direction, up to the fill's default meet
// tolerance (the largest gap a fill still closes): a loop that runs back over itself encloses
// nothing, and the fill's corner and side solves would divide by its zero width.
void requireDistinctBoundaries(const std::vector<Curve3d>& curves)
{
    for (size_t j = 1; j < curves.size(); ++j) {
        for (size_t k = 0; k < j; ++k) {
            const Curve3d& a = curves[k];
            const Curve3d& b = curves[j];
            const double tol = kDefaultMeetRelative * std::max(a.controlSize(), b.controlSize());
            const auto same = [&](bool reversed) {
                for (int i = 0; i <= kBoundarySamples; ++i) {
                    const double t = static_cast<double>(i) / kBoundarySamples;
                    const double ua = a.domainStart() + t * (a.domainEnd() - a.domainStart());
                    const double tb = reversed ? 1.0 - t : t;
                    const double ub = b.domainStart() + tb * (b.domainEnd() - b.domainStart());
                    if ((a.evaluate(ua) - b.evaluate(ub)).norm() > tol) return false;
                }
                return true;
            };
            if (same(false) || same(true))
                throw GeometryError("curves[" + std::to_string(j) + "]: the same curve as curves[" + std::to_string(k) +
                                    "]; fill boundaries must be distinct curves");
        }
    }
}

void checkInputs(SurfaceMode mode, const std::vector<Curve3d>& c, const SurfaceOptions& o)
{
    requireFinite(o.axisPoint.allFinite() && o.axisDirection.allFinite(), "axis");
    requireFinite(std::isfinite(o.angleDegrees), "angle");
    requireFinite(o.direction.allFinite(), "direction");
    requireFinite(std::isfinite(o.tolerance), "tolerance");
    requireFinite(std::isfinite(o.fillAngleToleranceDegrees), "angle_tolerance");
    requireNotCollapsed(c, "curves");
    if (mode == SurfaceMode::Extrude && o.extrudePath && o.extrudePath->isCollapsed())
        throw GeometryError("path: degenerate, all control points coincide");
    if (mode == SurfaceMode::Fill) requireDistinctBoundaries(c);
}

// The last line of defence: whatever a mode computed, a surface with a NaN or infinite number
// never leaves the entry point (the JSON writer would print null, the GUI would draw nothing).
void checkResult(const Surface3d& s, double deviation)
{
    for (const auto& q : s.points())
        if (!q.allFinite()) throw GeometryError("surface: the construction produced a non-finite control point (input too large)");
    for (double w : s.weights())
        if (!std::isfinite(w)) throw GeometryError("surface: the construction produced a non-finite weight");
    if (std::isnan(deviation)) throw GeometryError("surface: the construction's deviation is not a number");
}

// The input curves are valid (finite) geometry, so a "points[i]: not a finite number" from a
// curve or surface the mode constructs means that its arithmetic overflowed: say so, naming the
// result rather than an input field the caller never gave.
template <class F>
auto overflowNamed(F&& f) -> decltype(f())
{
    try {
        return f();
    } catch (const GeometryError& e) {
        const std::string m = e.what();
        const bool constructed = m.rfind("points[", 0) == 0 || m.rfind("weights[", 0) == 0;
        if (constructed && m.find(": not a finite number") != std::string::npos)
            throw GeometryError("surface: the construction overflows double precision (coordinates too large)");
        throw;
    }
}

SurfaceBuild checked(SurfaceBuild b)
{
    checkResult(b.surface, b.maxDeviation);
    return b;
}

}  // namespace

SurfaceMode parseSurfaceMode(const std::string& name)
{
    for (const auto& [mode, text] : kNames) {
        if (name == text) return mode;
    }
    throw std::invalid_argument("mode: unknown mode \"" + name +
                                "\" (fill, revolve, extrude, sweep, loft, boundary-rotation, rail-rotation)");
}

const char* surfaceModeName(SurfaceMode mode)
{
    for (const auto& [m, text] : kNames) {
        if (m == mode) return text;
    }
    return "?";
}

void checkCurveCount(SurfaceMode mode, size_t count)
{
    switch (mode) {
    case SurfaceMode::Fill: return requireCount(count, 2, 4, "2, 3 or 4 boundary curves");
    case SurfaceMode::Revolve:
    case SurfaceMode::Extrude: return requireCount(count, 1, 1, "one profile curve");
    case SurfaceMode::Sweep: return requireCount(count, 2, 2, "[profile, path]");
    case SurfaceMode::Loft: return;
    case SurfaceMode::BoundaryRotation: return requireCount(count, 2, 2, "[left outline, right outline]");
    case SurfaceMode::RailRotation: return requireCount(count, 3, 3, "[rail 1, rail 2, profile]");
    }
    throw std::invalid_argument("mode: unknown surface mode");
}

SurfaceBuild buildSurface(SurfaceMode mode, const std::vector<Curve3d>& c, const SurfaceOptions& o)
{
    checkCurveCount(mode, c.size());
    checkInputs(mode, c, o);
    SurfaceBuild b = overflowNamed([&] { return buildUnchecked(mode, c, o); });
    checkResult(b.surface, b.maxDeviation);
    return b;
}

GordonResult buildGordon(const std::vector<Curve3d>& u, const std::vector<Curve3d>& v, const GordonOptions& o)
{
    requireFinite(std::isfinite(o.meetTolerance), "tolerance");
    requireNotCollapsed(u, "curves");
    requireNotCollapsed(v, "v_curves");
    GordonResult g = overflowNamed([&] { return gordon(u, v, o); });
    checkResult(g.surface, g.maxGap);
    return g;
}

namespace {

SurfaceBuild buildUnchecked(SurfaceMode mode, const std::vector<Curve3d>& c, const SurfaceOptions& o)
{
    switch (mode) {
    case SurfaceMode::Fill: return fillBuild(FillBuilder(c, fillOptions(o)), o);
    case SurfaceMode::Revolve: return {revolve(c[0], Axis{o.axisPoint, o.axisDirection}, o.angleDegrees)};
    case SurfaceMode::Extrude: return {o.extrudePath ? extrude(c[0], *o.extrudePath) : extrude(c[0], o.direction)};
    case SurfaceMode::Sweep:
        return renamingPath([&] { return sweepBuild(sweep(c[0], c[1], SweepOptions{o.tolerance, 513})); });
    case SurfaceMode::Loft: return {loft(c, loftOptions(o))};
    case SurfaceMode::BoundaryRotation: return approximated(boundaryRotation(c[0], c[1], {o.tolerance, 2049}));
    case SurfaceMode::RailRotation: return approximated(railRotation(c[0], c[1], c[2], {o.tolerance, 2049}));
    }
    throw std::invalid_argument("mode: unknown surface mode");
}

}  // namespace

SurfaceBuilder::SurfaceBuilder(SurfaceMode mode, const std::vector<Curve3d>& curves, const SurfaceOptions& options)
    : mode_(mode), options_(options)
{
    reset(curves);
}

SurfaceBuilder::~SurfaceBuilder() = default;
SurfaceBuilder::SurfaceBuilder(SurfaceBuilder&&) noexcept = default;
SurfaceBuilder& SurfaceBuilder::operator=(SurfaceBuilder&&) noexcept = default;

const SurfaceBuild& SurfaceBuilder::reset(const std::vector<Curve3d>& c)
{
    checkCurveCount(mode_, c.size());
    checkInputs(mode_, c, options_);
    // Each branch builds aside and commits only a checked result: a failed rebuild keeps the last
    // good surface (and builder), as update() promises.
    switch (mode_) {
    case SurfaceMode::Fill: {
        auto b = std::make_unique<FillBuilder>(c, fillOptions(options_));
        auto out = std::make_unique<SurfaceBuild>(checked(fillBuild(*b, options_)));
        fill_ = std::move(b);
        build_ = std::move(out);
        break;
    }
    case SurfaceMode::Loft: {
        auto b = std::make_unique<LoftBuilder>(c, loftOptions(options_));
        auto out = std::make_unique<SurfaceBuild>(checked(SurfaceBuild{b->surface()}));
        loft_ = std::move(b);
        build_ = std::move(out);
        break;
    }
    case SurfaceMode::Sweep: {
        auto b = renamingPath(
            [&] { return std::make_unique<SweepBuilder>(c[0], c[1], SweepOptions{options_.tolerance, 513}); });
        auto out = std::make_unique<SurfaceBuild>(checked(sweepBuild(b->result())));
        sweep_ = std::move(b);
        build_ = std::move(out);
        break;
    }
    default: build_ = std::make_unique<SurfaceBuild>(buildSurface(mode_, c, options_));
    }
    return *build_;
}

const SurfaceBuild& SurfaceBuilder::update(const std::vector<Curve3d>& c)
{
    checkCurveCount(mode_, c.size());
    checkInputs(mode_, c, options_);
    switch (mode_) {
    case SurfaceMode::Fill:
        fill_->update(c);
        build_ = std::make_unique<SurfaceBuild>(checked(fillBuild(*fill_, options_)));
        break;
    case SurfaceMode::Loft: build_ = std::make_unique<SurfaceBuild>(checked(SurfaceBuild{loft_->update(c)})); break;
    case SurfaceMode::Sweep:
        build_ = std::make_unique<SurfaceBuild>(
            checked(sweepBuild(renamingPath([&] { return sweep_->update(c[0], c[1]); }))));
        break;
    default: build_ = std::make_unique<SurfaceBuild>(buildSurface(mode_, c, options_));
    }
    return *build_;
}

}  // namespace sculptline::solvers::surfaces
