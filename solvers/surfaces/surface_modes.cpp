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
    switch (mode_) {
    case SurfaceMode::Fill: {
        auto b = std::make_unique<FillBuilder>(c, fillOptions(options_));
        build_ = std::make_unique<SurfaceBuild>(fillBuild(*b, options_));
        fill_ = std::move(b);
        break;
    }
    case SurfaceMode::Loft: {
        auto b = std::make_unique<LoftBuilder>(c, loftOptions(options_));
        build_ = std::make_unique<SurfaceBuild>(SurfaceBuild{b->surface()});
        loft_ = std::move(b);
        break;
    }
    case SurfaceMode::Sweep: {
        auto b = renamingPath(
            [&] { return std::make_unique<SweepBuilder>(c[0], c[1], SweepOptions{options_.tolerance, 513}); });
        build_ = std::make_unique<SurfaceBuild>(sweepBuild(b->result()));
        sweep_ = std::move(b);
        break;
    }
    default: build_ = std::make_unique<SurfaceBuild>(buildSurface(mode_, c, options_));
    }
    return *build_;
}

const SurfaceBuild& SurfaceBuilder::update(const std::vector<Curve3d>& c)
{
    checkCurveCount(mode_, c.size());
    switch (mode_) {
    case SurfaceMode::Fill:
        fill_->update(c);
        build_ = std::make_unique<SurfaceBuild>(fillBuild(*fill_, options_));
        break;
    case SurfaceMode::Loft: build_ = std::make_unique<SurfaceBuild>(SurfaceBuild{loft_->update(c)}); break;
    case SurfaceMode::Sweep:
        build_ = std::make_unique<SurfaceBuild>(sweepBuild(renamingPath([&] { return sweep_->update(c[0], c[1]); })));
        break;
    default: build_ = std::make_unique<SurfaceBuild>(buildSurface(mode_, c, options_));
    }
    return *build_;
}

}  // namespace sculptline::solvers::surfaces
