#pragma once
// Surface analysis display modes drawn on a surface node's own mesh (scene/geometry_nodes.h):
// curvature colouring (Gaussian K, mean H; solvers/bspline/surface_curvature.h) and zebra stripes.
//
// Curvature: per-vertex colours through a diverging map, blue negative, white zero, red positive,
// over a symmetric range +-R, R the kRangePercentile-th percentile of |value| over the surface's
// vertices, so that one spike (a pole, a crease) does not wash the rest out to white.
// Zebra: reflection lines of an environment of horizontal light bands around the viewer (the
// classic environment-map zebra, Klass, "Correction of local surface irregularities using
// reflection lines", CAD 12(2), 1980): the eye ray reflected at the vertex, r = e - 2 (e.n) n, in
// camera space; its elevation angle asin(r.up) picks the band. One texture coordinate per vertex
// into a black/white SoTexture2, so stripe edges are sharp inside the triangles. The stripes follow
// the camera (an SoNodeSensor on it): continuous stripes across a boundary mean G1, stripes
// without kinks there mean G2.
// Both modes are drawn unlit (SoLightModel BASE_COLOR): the colours are the legend's, not shaded.
#include "scene/geometry_nodes.h"
#include "model/entity_kind.h"
#include "solvers/bspline/surface_curvature.h"

#include <Inventor/SbColor.h>
#include <Inventor/SbVec3f.h>

#include <map>
#include <memory>
#include <vector>

class SoCamera;
class SoNodeSensor;
class SoSensor;
class SoSeparator;

namespace sculptline::scene {

enum class SurfaceDisplay { Shaded, Zebra, Gaussian, Mean };

/// The percentile of |value| that spans the colour range (values beyond it are drawn saturated).
constexpr double kRangePercentile = 0.95;
/// Black stripes over the half circle of reflected-ray elevations (-90 to +90 degrees).
constexpr int kDefaultZebraStripes = 16;
constexpr int kMinZebraStripes = 2;
constexpr int kMaxZebraStripes = 128;
/// A curvature range below this (over the surface's size, or its square for K) is flat: a radius
/// a million times the surface's size. The colour range never shrinks below it, so rounding noise
/// on a plane (K ~ 1e-17) stays white instead of being stretched to saturated blue and red.
constexpr double kFlatCurvature = 1e-6;
/// Texels per black + white pair of the stripe texture: enough for a straight, sharp edge under
/// linear filtering at any stripe width on screen.
constexpr int kStripeTexels = 256;

/// The diverging map: t in [-1, 1] (clamped) to blue (-1), white (0), red (+1), linear in between.
SbColor divergingColor(double t);
/// The kRangePercentile-th percentile of |values| (nearest rank, finite values only); 0 if none.
double robustRange(const std::vector<double>& values, double percentile = kRangePercentile);

/// What the eye sees of the environment at a vertex, for the zebra.
struct ZebraView {
    SbVec3f eye{0, 0, 0};         ///< camera position (perspective) in world coordinates
    SbVec3f direction{0, 0, -1};  ///< view direction (unit), used for every vertex of an orthographic camera
    SbVec3f up{0, 1, 0};          ///< camera up (unit)
    bool perspective = true;
};
/// The zebra texture coordinate: stripes * (asin(r.up) / pi + 1/2); one black stripe per unit.
float zebraCoordinate(const SbVec3f& point, const SbVec3f& normal, const ZebraView& view, int stripes);

/// What a curvature-coloured surface's colours stand for.
struct CurvatureLegend {
    SurfaceDisplay mode = SurfaceDisplay::Shaded;
    double range = 0.0;  ///< the colours saturate at -range (blue) and +range (red)
    double min = 0.0, max = 0.0;  ///< over the defined vertices
};

/// Draws the analysis modes on surface nodes. The model view calls apply() after every build or
/// in-place rewrite of a surface node; the work per call is one pass over the node's vertices.
class SurfaceAnalysisDisplay {
public:
    SurfaceAnalysisDisplay();
    ~SurfaceAnalysisDisplay();
    SurfaceAnalysisDisplay(const SurfaceAnalysisDisplay&) = delete;
    SurfaceAnalysisDisplay& operator=(const SurfaceAnalysisDisplay&) = delete;

    /// The camera the zebra is seen through (its changes recompute the stripes); null detaches.
    void setCamera(SoCamera* camera);
    SoCamera* camera() const;
    /// Black stripes over the elevations, clamped to [kMinZebraStripes, kMaxZebraStripes].
    void setStripes(int stripes);
    int stripes() const { return stripes_; }

    /// Draws surface `id`'s node in `mode`. `node` is a surface node whose vertices and normals
    /// (`fields`) sample `surface` on the grid u x v (vertex r * v.size() + c). Shaded restores
    /// the plain node.
    void apply(model::EntityId id, SoSeparator* node, const SurfaceNodeFields& fields, const solvers::Surface3d& surface,
               const std::vector<double>& u, const std::vector<double>& v, SurfaceDisplay mode);
    /// Forgets surface `id` (its node is gone or no longer analysed).
    void remove(model::EntityId id);

    /// The legend of a curvature-coloured surface, or null.
    const CurvatureLegend* legend(model::EntityId id) const;
    /// The per-vertex values of a curvature-coloured surface (K or H, undefined ones filled from
    /// the nearest defined vertex of their grid column), or null.
    const std::vector<double>* values(model::EntityId id) const;
    /// The parameter grid (rows u, columns v) of an analysed surface's vertices, or null.
    const std::vector<double>* gridU(model::EntityId id) const;
    const std::vector<double>* gridV(model::EntityId id) const;
    /// The display mode surface `id` is drawn in (Shaded when not analysed).
    SurfaceDisplay mode(model::EntityId id) const;
    /// apply() calls that coloured or striped a surface, and camera-driven zebra updates.
    int recolours() const { return recolours_; }
    int cameraUpdates() const { return cameraUpdates_; }

private:
    struct Entry;
    void colourCurvature(Entry& entry, const solvers::Surface3d& surface);
    void stripe(Entry& entry);
    ZebraView zebraView() const;
    static void cameraChanged(void* self, SoSensor* sensor);

    std::map<model::EntityId, std::unique_ptr<Entry>> entries_;
    std::unique_ptr<SoNodeSensor> cameraSensor_;
    ZebraView lastView_;  ///< the view the stripes were last made for by a camera change
    int stripes_ = kDefaultZebraStripes;
    int recolours_ = 0;
    int cameraUpdates_ = 0;
};

}  // namespace sculptline::scene
