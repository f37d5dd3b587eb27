#pragma once
// Loft / skinning: a surface through section curves (The NURBS Book §10.3; seed 000's
// "interpolation mode"; thesis mode 3 when the sections come from a moving curve).
#include "solvers/bspline/bspline_surface.h"
#include "solvers/surfaces/compatible_curves.h"
#include "solvers/surfaces/interpolation.h"

#include <memory>
#include <optional>
#include <vector>

namespace sculptline::solvers::surfaces {

struct LoftOptions {
    /// Degree across the sections, lowered to sections - 1 when there are fewer sections (>= 1).
    int crossDegree = 3;
};

/// S(u, v): u runs along the sections (made compatible: common degree and knots on [0, 1]; a
/// section drawn the other way round than its predecessor is reversed first; a closed section after
/// a closed one is turned to wind the same way and, if periodic, opened at its point nearest the
/// predecessor's seam, so closed sections give a tube closed along u), v across them; S(u, v_k) = section k exactly (homogeneous control rows are interpolated, so
/// rational sections are met exactly too). v_k are averaged chord lengths between the sections'
/// control points (The NURBS Book eq. 10.8); knots V by averaging (eq. 9.8).
/// @throws GeometryError ("curves: ...") for fewer than two sections, coincident consecutive
///         sections, or rational sections whose interpolated weights would not stay positive.
Surface3d loft(const std::vector<Curve3d>& sections, const LoftOptions& options = {});

/// Incremental loft for dragging: the compatible layout, the cross parameters and the LU factor of
/// the cross interpolation are computed once; update() re-solves for moved sections. While a drag
/// lasts the cross parameters stay those of the first build (so the surface is a smooth function of
/// the motion); call reset() when the drag ends to re-parameterize.
class LoftBuilder {
public:
    explicit LoftBuilder(const std::vector<Curve3d>& sections, const LoftOptions& options = {});

    /// Replaces section `index` and rebuilds. If its knots do not fit the layout, the layout is
    /// recomputed (a full build).
    const Surface3d& update(int index, const Curve3d& section);
    /// Replaces every section (same count) and rebuilds with the kept factorization.
    const Surface3d& update(const std::vector<Curve3d>& sections);
    /// Full rebuild: new layout, parameters and factorization.
    const Surface3d& reset(const std::vector<Curve3d>& sections);

    const Surface3d& surface() const { return *surface_; }
    const std::vector<double>& crossParameters() const { return interpolator_->params(); }

private:
    void solve();
    bool setSection(int index, const Curve3d& section);
    /// The section normalized as it was laid out at the last reset (opened at its seam, turned).
    Curve3d laidOut(int index, const Curve3d& section) const;

    LoftOptions options_;
    CurveLayout layout_;
    bool rational_ = false;
    std::vector<bool> reversed_;  // section k was turned to run like section k - 1
    std::vector<std::optional<double>> seams_;  // closed section k opened at this parameter
    int columns_ = 0;  // homogeneous coordinates per control point (3 or 4)
    std::unique_ptr<CurveInterpolator> interpolator_;
    ControlMatrix data_;  // row k: section k's control rows side by side
    std::unique_ptr<Surface3d> surface_;
};

/// The surface with U and V exchanged (point (i, j) becomes (j, i)).
Surface3d transposed(const Surface3d& s);

}  // namespace sculptline::solvers::surfaces
