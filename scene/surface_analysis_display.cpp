#include "scene/surface_analysis_display.h"

#include "solvers/math_constants.h"

#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoComplexity.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTexture2.h>
#include <Inventor/nodes/SoTextureCoordinate2.h>
#include <Inventor/nodes/SoTextureCoordinateBinding.h>
#include <Inventor/sensors/SoNodeSensor.h>

#include <algorithm>
#include <cmath>

namespace sculptline::scene {
namespace {

const SbColor kNegative(0.15f, 0.3f, 1.0f);
const SbColor kZero(1.0f, 1.0f, 1.0f);
const SbColor kPositive(1.0f, 0.15f, 0.1f);
const char* const kWrapperName = "SurfaceAnalysis";

/// The face set of a surface node (scene/geometry_nodes.cpp's makeMeshNode), or -1.
int faceSetIndex(SoSeparator* node)
{
    for (int k = 0; k < node->getNumChildren(); ++k)
        if (node->getChild(k)->isOfType(SoIndexedFaceSet::getClassTypeId())) return k;
    return -1;
}

/// Undefined values (degenerate metric) take the nearest defined one in their grid column, then
/// row: the limit from inside the surface at a revolved profile's pole.
void fillUndefined(const std::vector<solvers::SurfaceCurvature>& k, int rows, int cols, bool gaussian, std::vector<double>& out)
{
    out.assign(k.size(), 0.0);
    std::vector<char> defined(k.size());
    for (size_t i = 0; i < k.size(); ++i) {
        defined[i] = k[i].defined;
        out[i] = gaussian ? k[i].gaussian : k[i].mean;
    }
    auto nearest = [&](int r, int c) {
        for (int d = 1; d < std::max(rows, cols); ++d) {
            for (int rr : {r - d, r + d})
                if (rr >= 0 && rr < rows && defined[static_cast<size_t>(rr * cols + c)]) return out[static_cast<size_t>(rr * cols + c)];
        }
        for (int d = 1; d < cols; ++d) {
            for (int cc : {c - d, c + d})
                if (cc >= 0 && cc < cols && defined[static_cast<size_t>(r * cols + cc)]) return out[static_cast<size_t>(r * cols + cc)];
        }
        return 0.0;
    };
    std::vector<double> filled = out;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            if (!defined[static_cast<size_t>(r * cols + c)]) filled[static_cast<size_t>(r * cols + c)] = nearest(r, c);
    out = std::move(filled);
}

SoTexture2* stripeTexture()
{
    // One black and one white stripe per texture period, repeated along s.
    std::vector<unsigned char> texels(kStripeTexels);
    for (int i = 0; i < kStripeTexels; ++i) texels[static_cast<size_t>(i)] = i < kStripeTexels / 2 ? 0 : 255;
    auto* texture = new SoTexture2;
    texture->image.setValue(SbVec2s(static_cast<short>(kStripeTexels), 1), 1, texels.data());
    texture->wrapS = SoTexture2::REPEAT;
    texture->wrapT = SoTexture2::CLAMP;
    texture->model = SoTexture2::MODULATE;
    return texture;
}

}  // namespace

SbColor divergingColor(double t)
{
    t = std::clamp(std::isfinite(t) ? t : 0.0, -1.0, 1.0);
    const SbColor& end = t < 0 ? kNegative : kPositive;
    const float a = static_cast<float>(std::abs(t));
    return kZero * (1.0f - a) + end * a;
}

double robustRange(const std::vector<double>& values, double percentile)
{
    std::vector<double> magnitudes;
    magnitudes.reserve(values.size());
    for (double x : values)
        if (std::isfinite(x)) magnitudes.push_back(std::abs(x));
    if (magnitudes.empty()) return 0.0;
    // Nearest rank: the smallest value with at least `percentile` of the values at or below it.
    const double rank = std::ceil(std::clamp(percentile, 0.0, 1.0) * static_cast<double>(magnitudes.size()));
    const size_t k = static_cast<size_t>(std::clamp(rank, 1.0, static_cast<double>(magnitudes.size()))) - 1;
    std::nth_element(magnitudes.begin(), magnitudes.begin() + static_cast<std::ptrdiff_t>(k), magnitudes.end());
    return magnitudes[k];
}

float zebraCoordinate(const SbVec3f& point, const SbVec3f& normal, const ZebraView& view, int stripes)
{
    SbVec3f e = view.perspective ? point - view.eye : view.direction;
    if (e.normalize() == 0.0f) e = view.direction;
    SbVec3f n = normal;
    if (n.normalize() == 0.0f) n = -e;
    // The reflected eye ray (either side of the surface gives the same r) and its elevation above
    // the camera's horizontal plane.
    const SbVec3f r = e - 2.0f * e.dot(n) * n;
    const double elevation = std::asin(std::clamp(static_cast<double>(r.dot(view.up)), -1.0, 1.0));
    return static_cast<float>(stripes * (elevation / solvers::kPi + 0.5));
}

struct SurfaceAnalysisDisplay::Entry {
    SoSeparator* node = nullptr;  ///< ref()ed while here
    SoSeparator* wrapper = nullptr;  ///< the "SurfaceAnalysis" separator around the face set
    SurfaceNodeFields fields;
    SurfaceDisplay mode = SurfaceDisplay::Shaded;
    std::vector<double> u, v;
    std::unique_ptr<solvers::CurvatureGrid> grid;
    std::vector<solvers::SurfaceCurvature> curvature;
    std::vector<double> values;
    CurvatureLegend legend;
    SoMaterial* colours = nullptr;
    SoTextureCoordinate2* texture = nullptr;

    ~Entry() { release(); }
    /// The plain node again: the face set back in the wrapper's place.
    void release()
    {
        if (!node) return;
        const int index = wrapper ? node->findChild(wrapper) : -1;
        if (index >= 0) node->replaceChild(index, wrapper->getChild(wrapper->getNumChildren() - 1));
        node->unref();
        node = nullptr;
        wrapper = nullptr;
    }
};

SurfaceAnalysisDisplay::SurfaceAnalysisDisplay() = default;

SurfaceAnalysisDisplay::~SurfaceAnalysisDisplay()
{
    entries_.clear();
    if (cameraSensor_) cameraSensor_->detach();
}

void SurfaceAnalysisDisplay::setCamera(SoCamera* camera)
{
    if (!cameraSensor_) cameraSensor_ = std::make_unique<SoNodeSensor>(&SurfaceAnalysisDisplay::cameraChanged, this);
    if (cameraSensor_->getAttachedNode() == camera) return;
    cameraSensor_->detach();
    if (camera) cameraSensor_->attach(camera);
    cameraChanged(this, nullptr);
}

SoCamera* SurfaceAnalysisDisplay::camera() const
{
    return cameraSensor_ ? static_cast<SoCamera*>(cameraSensor_->getAttachedNode()) : nullptr;
}

void SurfaceAnalysisDisplay::setStripes(int stripes)
{
    stripes_ = std::clamp(stripes, kMinZebraStripes, kMaxZebraStripes);
    for (auto& [id, entry] : entries_)
        if (entry->mode == SurfaceDisplay::Zebra) stripe(*entry);
}

void SurfaceAnalysisDisplay::cameraChanged(void* self, SoSensor* sensor)
{
    auto* display = static_cast<SurfaceAnalysisDisplay*>(self);
    // Only a new position or orientation changes what is reflected; a zoom of an orthographic
    // camera, a new focal distance or clipping planes leave the stripes as they are.
    const ZebraView view = display->zebraView();
    const ZebraView& last = display->lastView_;
    if (sensor && view.eye == last.eye && view.direction == last.direction && view.up == last.up && view.perspective == last.perspective)
        return;
    display->lastView_ = view;
    bool any = false;
    for (auto& [id, entry] : display->entries_) {
        if (entry->mode != SurfaceDisplay::Zebra) continue;
        display->stripe(*entry);
        any = true;
    }
    if (any) ++display->cameraUpdates_;
}

ZebraView SurfaceAnalysisDisplay::zebraView() const
{
    ZebraView view{SbVec3f(0, 0, 0), SbVec3f(0, 0, -1), SbVec3f(0, 1, 0), false};
    const SoCamera* camera = this->camera();
    if (!camera) return view;
    const SbRotation orientation = camera->orientation.getValue();
    orientation.multVec(SbVec3f(0, 0, -1), view.direction);
    orientation.multVec(SbVec3f(0, 1, 0), view.up);
    view.eye = camera->position.getValue();
    view.perspective = camera->isOfType(SoPerspectiveCamera::getClassTypeId());
    return view;
}

void SurfaceAnalysisDisplay::apply(model::EntityId id, SoSeparator* node, const SurfaceNodeFields& fields,
                                   const solvers::Surface3d& surface, const std::vector<double>& u, const std::vector<double>& v,
                                   SurfaceDisplay mode)
{
    auto it = entries_.find(id);
    const bool wrapped = it != entries_.end() && it->second->node == node && it->second->wrapper;
    const bool usable = node && fields.coordinates && fields.normals && (wrapped || faceSetIndex(node) >= 0) &&
                        fields.coordinates->point.getNum() == static_cast<int>(u.size() * v.size());
    if (mode == SurfaceDisplay::Shaded || !usable) {
        if (it != entries_.end()) entries_.erase(it);
        return;
    }
    if (it == entries_.end()) it = entries_.emplace(id, std::make_unique<Entry>()).first;
    Entry& entry = *it->second;
    if (entry.node != node || entry.mode != mode) {
        node->ref();  // before release(): the same node, unwrapped for another mode, must not die
        entry.release();  // the face set is a child of `node` again
        entry.node = node;
        entry.mode = mode;
        const int index = faceSetIndex(node);
        SoNode* faces = node->getChild(index);
        entry.wrapper = new SoSeparator;
        entry.wrapper->setName(kWrapperName);
        auto* light = new SoLightModel;
        light->model = SoLightModel::BASE_COLOR;
        entry.wrapper->addChild(light);
        entry.colours = nullptr;
        entry.texture = nullptr;
        if (mode == SurfaceDisplay::Zebra) {
            auto* white = new SoBaseColor;
            white->rgb = kZero;
            entry.wrapper->addChild(white);
            entry.wrapper->addChild(stripeTexture());
            entry.texture = new SoTextureCoordinate2;
            entry.wrapper->addChild(entry.texture);
            auto* binding = new SoTextureCoordinateBinding;
            binding->value = SoTextureCoordinateBinding::PER_VERTEX_INDEXED;  // textureCoordIndex empty: coordIndex
            entry.wrapper->addChild(binding);
        } else {
            entry.colours = new SoMaterial;
            entry.wrapper->addChild(entry.colours);
            auto* binding = new SoMaterialBinding;
            binding->value = SoMaterialBinding::PER_VERTEX_INDEXED;  // materialIndex empty: coordIndex
            entry.wrapper->addChild(binding);
        }
        entry.wrapper->addChild(faces);
        node->replaceChild(index, entry.wrapper);
    }
    entry.fields = fields;
    const bool sameGrid = entry.u == u && entry.v == v;
    if (!sameGrid) {
        entry.u = u;
        entry.v = v;
    }
    if (mode == SurfaceDisplay::Zebra) {
        entry.grid.reset();
        stripe(entry);
    } else {
        // A drag rewrites the same grid with new control points: the kept basis serves every event.
        if (!entry.grid || !sameGrid || !entry.grid->fits(surface)) entry.grid = std::make_unique<solvers::CurvatureGrid>(surface, u, v);
        colourCurvature(entry, surface);
    }
    ++recolours_;
}

void SurfaceAnalysisDisplay::colourCurvature(Entry& entry, const solvers::Surface3d& surface)
{
    entry.grid->evaluate(surface, entry.curvature);
    const bool gaussian = entry.mode == SurfaceDisplay::Gaussian;
    const int rows = static_cast<int>(entry.u.size()), cols = static_cast<int>(entry.v.size());
    fillUndefined(entry.curvature, rows, cols, gaussian, entry.values);
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : surface.points()) box.extend(p);
    const double size = std::max(box.diagonal().norm(), 1e-300);
    const double flat = gaussian ? (kFlatCurvature / size) * (kFlatCurvature / size) : kFlatCurvature / size;
    CurvatureLegend& legend = entry.legend;
    legend.mode = entry.mode;
    legend.range = std::max(robustRange(entry.values), flat);
    legend.min = legend.max = entry.values.empty() ? 0.0 : entry.values.front();
    for (double x : entry.values) {
        legend.min = std::min(legend.min, x);
        legend.max = std::max(legend.max, x);
    }
    const int count = static_cast<int>(entry.values.size());
    entry.colours->diffuseColor.setNum(count);
    SbColor* out = entry.colours->diffuseColor.startEditing();
    for (int i = 0; i < count; ++i) out[i] = divergingColor(entry.values[static_cast<size_t>(i)] / legend.range);
    entry.colours->diffuseColor.finishEditing();
}

void SurfaceAnalysisDisplay::stripe(Entry& entry)
{
    if (!entry.texture || !entry.fields.coordinates || !entry.fields.normals) return;
    const ZebraView view = zebraView();
    const int count = entry.fields.coordinates->point.getNum();
    const SbVec3f* points = entry.fields.coordinates->point.getValues(0);
    const SbVec3f* normals = entry.fields.normals->vector.getValues(0);
    const int withNormals = std::min(count, entry.fields.normals->vector.getNum());
    entry.texture->point.setNum(count);
    SbVec2f* out = entry.texture->point.startEditing();
    for (int i = 0; i < count; ++i)
        out[i] = SbVec2f(zebraCoordinate(points[i], i < withNormals ? normals[i] : SbVec3f(0, 0, 0), view, stripes_), 0.5f);
    entry.texture->point.finishEditing();
}

SurfaceDisplay SurfaceAnalysisDisplay::mode(model::EntityId id) const
{
    const auto it = entries_.find(id);
    return it != entries_.end() ? it->second->mode : SurfaceDisplay::Shaded;
}

void SurfaceAnalysisDisplay::remove(model::EntityId id) { entries_.erase(id); }

const CurvatureLegend* SurfaceAnalysisDisplay::legend(model::EntityId id) const
{
    const auto it = entries_.find(id);
    return it != entries_.end() && it->second->mode != SurfaceDisplay::Zebra ? &it->second->legend : nullptr;
}

const std::vector<double>* SurfaceAnalysisDisplay::gridU(model::EntityId id) const
{
    const auto it = entries_.find(id);
    return it != entries_.end() ? &it->second->u : nullptr;
}

const std::vector<double>* SurfaceAnalysisDisplay::gridV(model::EntityId id) const
{
    const auto it = entries_.find(id);
    return it != entries_.end() ? &it->second->v : nullptr;
}

const std::vector<double>* SurfaceAnalysisDisplay::values(model::EntityId id) const
{
    const auto it = entries_.find(id);
    return it != entries_.end() && it->second->mode != SurfaceDisplay::Zebra ? &it->second->values : nullptr;
}

}  // namespace sculptline::scene
