#include "model/document_solids.h"
#include "model/document.h"

#include "solvers/io/geometry_json.h"

#include <Eigen/Geometry>

#include <cmath>
#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace sculptline::model {
namespace io = solvers::io;
using nlohmann::json;

namespace {

/// Edge of the plane of a fresh sheet: a sheet of paper at arm's length (model units, mm).
constexpr double kFreshPlaneSize = 120.0;
/// Largest coordinate or size the scene accepts, in model units (a kilometre in millimetres): Coin
/// draws in float, whose resolution at 1e6 is 0.06 units, and beyond ~1e38 not at all.
constexpr double kMaxExtent = 1e6;

/// Grid lines per edge beyond which a grid is a fill, not lines (and a typo like spacing 0.0001).
constexpr double kMaxGridLines = 2000.0;

double positive(const json& j, const std::string& path)
{
    const double v = io::numberFromJson(j, path);
    if (!(v > 0.0)) throw io::InputError(path + ": must be positive");
    if (v > kMaxExtent) throw io::InputError(path + ": must not exceed 1e6 model units");
    return v;
}

void checkExtent(const Eigen::Vector3d& p, const std::string& path)
{
    if (p.cwiseAbs().maxCoeff() > kMaxExtent) throw io::InputError(path + ": coordinates must lie within +-1e6 model units");
}

template <typename Points>
void checkExtent(const Points& points, const std::string& path)
{
    for (size_t i = 0; i < points.size(); ++i) checkExtent(points[i], path + ".points[" + std::to_string(i) + "]");
}

/// The array member `key` of j, or an empty array when absent.
const json& optionalArray(const json& j, const std::string& key)
{
    static const json kEmpty = json::array();
    const auto it = j.find(key);
    if (it == j.end()) return kEmpty;
    if (!it->is_array()) throw io::InputError(key + ": must be an array");
    return *it;
}

/// "references": [{"path": absolute, "relative"?: from the document's folder}] (reference .iv files;
/// their contents are read and validated by the program that shows them, not here).
std::vector<ReferenceSpec> referencesFromJson(const json& refs)
{
    std::vector<ReferenceSpec> out;
    auto text = [](const json& j, const std::string& path) {
        if (!j.is_string() || j.get_ref<const std::string&>().empty()) throw io::InputError(path + ": must be a non-empty string");
        const std::string& s = j.get_ref<const std::string&>();
        if (s.find('\0') != std::string::npos) throw io::InputError(path + ": must not contain a NUL character");
        return s;
    };
    for (size_t i = 0; i < refs.size(); ++i) {
        const std::string path = "references[" + std::to_string(i) + "]";
        if (!refs[i].is_object()) throw io::InputError(path + ": must be a JSON object");
        ReferenceSpec r;
        r.path = text(io::member(refs[i], "path", path), path + ".path");
        if (const auto it = refs[i].find("relative"); it != refs[i].end()) r.relative = text(*it, path + ".relative");
        out.push_back(std::move(r));
    }
    return out;
}

PlaneSpec planeFromJson(const json& j, const std::string& path)
{
    if (!j.is_object()) throw io::InputError(path + ": must be a JSON object");
    PlaneSpec p;
    p.origin = io::pointFromJson(io::member(j, "origin", path), path + ".origin");
    checkExtent(p.origin, path + ".origin");
    const Eigen::Vector3d n = io::pointFromJson(io::member(j, "normal", path), path + ".normal");
    if (!(n.norm() > 0.0)) throw io::InputError(path + ".normal: must not be zero");
    p.normal = n.normalized();
    p.size = positive(io::member(j, "size", path), path + ".size");
    if (const auto it = j.find("xAxis"); it != j.end()) {
        p.xAxis = io::pointFromJson(*it, path + ".xAxis");
        if (!(p.xAxis.norm() > 0.0)) throw io::InputError(path + ".xAxis: must not be zero");
        if (p.xAxis.normalized().cross(p.normal).norm() < 1e-6) throw io::InputError(path + ".xAxis: must not be parallel to the normal");
    }
    if (const auto it = j.find("rotation"); it != j.end()) {
        if (!it->is_array() || it->size() != 4) throw io::InputError(path + ".rotation: must be a quaternion [x, y, z, w]");
        double q[4];
        for (int k = 0; k < 4; ++k) q[k] = io::numberFromJson((*it)[k], path + ".rotation[" + std::to_string(k) + "]");
        const Eigen::Quaterniond rotation(q[3], q[0], q[1], q[2]);
        if (std::abs(rotation.norm() - 1.0) > 1e-6) throw io::InputError(path + ".rotation: must be a unit quaternion");
        if ((rotation * Eigen::Vector3d::UnitZ() - p.normal).norm() > 1e-6) throw io::InputError(path + ".rotation: does not match normal");
        p.rotation = rotation;
    }
    if (const auto it = j.find("id"); it != j.end()) p.id = io::integerFromJson(*it, path + ".id", 1, 1 << 30);
    return p;
}

GridSpec gridFromJson(const json& j)
{
    if (!j.is_object()) throw io::InputError("grid: must be a JSON object");
    GridSpec g;
    g.size = positive(io::member(j, "size", "grid"), "grid.size");
    g.spacing = positive(io::member(j, "spacing", "grid"), "grid.spacing");
    if (g.spacing > g.size) throw io::InputError("grid.spacing: must not exceed grid.size");
    if (g.size / g.spacing > kMaxGridLines) throw io::InputError("grid.spacing: too small for grid.size (over 2000 lines)");
    return g;
}

/// The optional "id" of a curve or surface (0 when absent), unique among all ids in `used`.
int entityId(const json& j, const std::string& path, std::set<int>& used)
{
    const auto it = j.find("id");
    if (it == j.end()) return 0;
    const int id = io::integerFromJson(*it, path + ".id", 1, 1 << 30);
    if (!used.insert(id).second) throw io::InputError(path + ".id: used by another entity");
    return id;
}

/// A surface's optional "construction"; its curves must be curves of `doc` with smaller ids than
/// the surface's (inputs are created first).
Eigen::Vector2d uvFromJson(const json& j, const std::string& path)
{
    if (!j.is_array() || j.size() != 2) throw io::InputError(path + ": expected [u, v]");
    return {io::numberFromJson(j[0], path + "[0]"), io::numberFromJson(j[1], path + "[1]")};
}

/// A sculpt's handles, bound, blocked points, distances and curve tangents (model/surface_recipe.h):
/// "points": [{"point": id, "uv": [u, v], "normal"?: bool}] (the points join the inputs after the
/// target curves), "bound": [[u, v]..], "blocked": [[i, j]..], "distances": [{"uv", "uv2",
/// "value"}], "curve_tangents": [{"curve": target curve id, "direction": [x, y, z]}].
void sculptFromJson(const json& construction, const std::string& at, int surfaceId, const SceneDocument& doc,
                    SceneDocument::ConstructedSurface& c)
{
    SurfaceRecipe& r = c.recipe;
    auto array = [&](const char* name) -> const json* {
        const auto it = construction.find(name);
        if (it == construction.end()) return nullptr;
        if (!it->is_array()) throw io::InputError(at + "." + name + ": expected an array");
        return &*it;
    };
    if (const json* points = array("points")) {
        for (size_t k = 0; k < points->size(); ++k) {
            const std::string field = at + ".points[" + std::to_string(k) + "]";
            const json& h = (*points)[k];
            if (!h.is_object()) throw io::InputError(field + ": expected {\"point\", \"uv\"}");
            SurfaceRecipe::Handle handle;
            const int id = io::integerFromJson(io::member(h, "point", field), field + ".point", 1, 1 << 30);
            if (std::none_of(doc.points.begin(), doc.points.end(), [id](const SceneDocument::PointSpec& p) { return p.id == id; }))
                throw io::InputError(field + ".point: no point has id " + std::to_string(id));
            if (surfaceId != 0 && id >= surfaceId) throw io::InputError(field + ".point: must be smaller than the surface's id");
            if (std::find(c.curves.begin(), c.curves.end(), id) != c.curves.end()) throw io::InputError(field + ".point: named twice");
            handle.point = static_cast<std::uint32_t>(id);
            handle.uv = uvFromJson(io::member(h, "uv", field), field + ".uv");
            if (const auto n = h.find("normal"); n != h.end()) {
                if (!n->is_boolean()) throw io::InputError(field + ".normal: expected true or false");
                handle.holdNormal = n->get<bool>();
            }
            r.handles.push_back(handle);
            c.curves.push_back(id);
        }
    }
    if (const json* bound = array("bound")) {
        if (bound->size() < 3 || bound->size() > 4096) throw io::InputError(at + ".bound: a closed polygon of 3 to 4096 points [u, v]");
        for (size_t k = 0; k < bound->size(); ++k) r.bound.push_back(uvFromJson((*bound)[k], at + ".bound[" + std::to_string(k) + "]"));
    }
    if (const json* blocked = array("blocked")) {
        for (size_t k = 0; k < blocked->size(); ++k) {
            const std::string field = at + ".blocked[" + std::to_string(k) + "]";
            if (!(*blocked)[k].is_array() || (*blocked)[k].size() != 2) throw io::InputError(field + ": expected [i, j]");
            r.blocked.push_back({io::integerFromJson((*blocked)[k][0], field + "[0]", 0, 1 << 20),
                                 io::integerFromJson((*blocked)[k][1], field + "[1]", 0, 1 << 20)});
        }
    }
    if (const json* distances = array("distances")) {
        for (size_t k = 0; k < distances->size(); ++k) {
            const std::string field = at + ".distances[" + std::to_string(k) + "]";
            const json& d = (*distances)[k];
            SurfaceRecipe::Distance spec;
            spec.uv = uvFromJson(io::member(d, "uv", field), field + ".uv");
            spec.uv2 = uvFromJson(io::member(d, "uv2", field), field + ".uv2");
            spec.distance = io::numberFromJson(io::member(d, "value", field), field + ".value");
            if (!(spec.distance >= 0.0)) throw io::InputError(field + ".value: a distance must be >= 0");
            r.distances.push_back(spec);
        }
    }
    if (const json* tangents = array("curve_tangents")) {
        for (size_t k = 0; k < tangents->size(); ++k) {
            const std::string field = at + ".curve_tangents[" + std::to_string(k) + "]";
            const json& t = (*tangents)[k];
            SurfaceRecipe::CurveTangent spec;
            const int id = io::integerFromJson(io::member(t, "curve", field), field + ".curve", 1, 1 << 30);
            if (std::find(c.curves.begin() + 1, c.curves.end(), id) == c.curves.end())
                throw io::InputError(field + ".curve: curve " + std::to_string(id) + " is not one of this sculpt's target curves");
            spec.curve = static_cast<std::uint32_t>(id);
            spec.direction = io::pointFromJson(io::member(t, "direction", field), field + ".direction");
            if (spec.direction.norm() == 0.0) throw io::InputError(field + ".direction: must not be the zero vector");
            r.curveTangents.push_back(spec);
        }
    }
}

std::optional<SceneDocument::ConstructedSurface> constructionFromJson(const json& surface, const std::string& path,
                                                                      int surfaceId, const SceneDocument& doc)
{
    const auto it = surface.find("construction");
    if (it == surface.end()) return std::nullopt;
    const std::string at = path + ".construction";
    if (!it->is_object()) throw io::InputError(at + ": must be an object");
    SceneDocument::ConstructedSurface c;
    c.id = surfaceId;
    // No extent check on the saved geometry: it is what the construction built from curves that
    // passed theirs, and a revolution or extrusion reaches beyond its curves (a profile 1e6 from
    // its axis sweeps a circle of that radius); refusing it made such a document fail to reopen.
    if (surface.contains("points")) c.saved = io::surfaceFromJson(surface, path);
    const json& mode = io::member(*it, "mode", at);
    if (!mode.is_string()) throw io::InputError(at + ".mode: expected a string");
    const std::optional<Construction> known = constructionFromName(mode.get<std::string>());
    if (!known) throw io::InputError(at + ".mode: unknown surface mode \"" + mode.get<std::string>() + "\"");
    c.recipe.mode = *known;
    const ConstructionInfo& info = describe(*known);
    const InputCount count = surfaceInputCount(c.recipe.mode);
    if (info.baseSurface) {
        // A sculpt: "base" is the surface it deforms, made before it; "curves" its targets.
        const int base = io::integerFromJson(io::member(*it, "base", at), at + ".base", 1, 1 << 30);
        const bool known = std::find(doc.surfaceIds.begin(), doc.surfaceIds.end(), base) != doc.surfaceIds.end() ||
                           std::any_of(doc.constructed.begin(), doc.constructed.end(),
                                       [base](const SceneDocument::ConstructedSurface& s) { return s.id == base; });
        if (!known || (surfaceId != 0 && base >= surfaceId))
            throw io::InputError(at + ".base: no surface with id " + std::to_string(base) + " comes before this one");
        c.curves.push_back(base);
    }
    const json& curves = io::member(*it, "curves", at);
    if (!curves.is_array()) throw io::InputError(at + ".curves: expected an array of curve ids");
    for (size_t k = 0; k < curves.size(); ++k) {
        const std::string field = at + ".curves[" + std::to_string(k) + "]";
        const int id = io::integerFromJson(curves[k], field, 1, 1 << 30);
        if (std::find(doc.curveIds.begin(), doc.curveIds.end(), id) == doc.curveIds.end())
            throw io::InputError(field + ": no curve has id " + std::to_string(id));
        if (surfaceId != 0 && id >= surfaceId) throw io::InputError(field + ": must be smaller than the surface's id");
        c.curves.push_back(id);
    }
    if (info.baseSurface) sculptFromJson(*it, at, surfaceId, doc, c);
    const int n = static_cast<int>(c.curves.size());
    if (info.options & kStiffnessOption) {
        if (const auto s = it->find("stiffness"); s != it->end()) {
            c.recipe.stiffness = io::numberFromJson(*s, at + ".stiffness");
            if (!(c.recipe.stiffness > 0.0 && c.recipe.stiffness <= 1.0)) throw io::InputError(at + ".stiffness: must be in (0, 1]");
        }
        if (const auto o = it->find("objective"); o != it->end()) {
            if (!o->is_string() || (*o != "force" && *o != "displacement"))
                throw io::InputError(at + ".objective: must be \"force\" or \"displacement\"");
            c.recipe.displacementObjective = *o == "displacement";
        }
    }
    if (n < count.min || n > count.max)
        throw io::InputError(at + ".curves: mode " + info.name + " takes " + std::to_string(count.min) + " to " +
                             std::to_string(count.max) + " curves");
    if (const auto a = it->find("angle"); a != it->end()) {
        c.recipe.angleDegrees = io::numberFromJson(*a, at + ".angle");
        if (!(c.recipe.angleDegrees > 0.0 && c.recipe.angleDegrees <= 360.0)) throw io::InputError(at + ".angle: must be in (0, 360]");
    }
    // Any finite direction is read: one the extrusion cannot use (zero, 1e300) leaves the surface
    // failed with the reason when the document opens, and the rest of the document intact.
    if (const auto d = it->find("direction"); d != it->end()) c.recipe.direction = io::pointFromJson(*d, at + ".direction");
    if (info.options & kUCurvesOption) c.recipe.uCurves = io::integerFromJson(io::member(*it, "u_curves", at), at + ".u_curves", 2, n - 2);
    if (const auto g = it->find("tangents"); g != it->end()) {
        // G1 fill: {"curve": boundary index, "surface": id of a surface made before this one}.
        if (!g->is_array() || !(info.options & kTangentsOption)) throw io::InputError(at + ".tangents: an array, for a fill only");
        for (size_t k = 0; k < g->size(); ++k) {
            const std::string field = at + ".tangents[" + std::to_string(k) + "]";
            SurfaceRecipe::Tangent t;
            t.boundary = io::integerFromJson(io::member((*g)[k], "curve", field), field + ".curve", 0, n - 1);
            const int surface = io::integerFromJson(io::member((*g)[k], "surface", field), field + ".surface", 1, 1 << 30);
            const bool known = std::find(doc.surfaceIds.begin(), doc.surfaceIds.end(), surface) != doc.surfaceIds.end() ||
                               std::any_of(doc.constructed.begin(), doc.constructed.end(),
                                           [surface](const SceneDocument::ConstructedSurface& s) { return s.id == surface; });
            if (!known || (surfaceId != 0 && surface >= surfaceId))
                throw io::InputError(field + ".surface: no surface with id " + std::to_string(surface) + " comes before this one");
            t.surface = static_cast<std::uint32_t>(surface);
            c.recipe.tangents.push_back(t);
        }
    }
    if (const auto t = it->find("tolerance"); t != it->end()) {
        c.recipe.tolerance = io::numberFromJson(*t, at + ".tolerance");
        if (!(c.recipe.tolerance >= 0.0)) throw io::InputError(at + ".tolerance: must not be negative");
    }
    return c;
}

/// The format and version fields, checked first: a newer document must be refused by its version,
/// not by whatever field of it this program does not know.
void checkFormat(const json& j)
{
    if (const auto it = j.find("format"); it != j.end() && *it != kDocumentFormat) {
        throw io::InputError(std::string("format: not a Sculptline document (expected \"") + kDocumentFormat + "\")");
    }
    if (const auto it = j.find("version"); it != j.end()) {
        const int version = io::integerFromJson(*it, "version", 1, 1 << 30);
        if (version > kDocumentVersion) {
            throw io::InputError("made by a newer Sculptline (version " + std::to_string(version) + "); this one reads up to " +
                                 std::to_string(kDocumentVersion));
        }
    }
}

}  // namespace

SceneDocument documentFromJson(const json& j)
{
    if (!j.is_object()) throw io::InputError("document: must be a JSON object");
    checkFormat(j);
    SceneDocument doc;
    if (const auto it = j.find("grid"); it != j.end()) doc.grid = gridFromJson(*it);
    const json& planes = optionalArray(j, "planes");
    // Two sets: a curve's "plane" must name a plane, not merely a used id (a curve's id passed).
    std::set<int> planeIds, usedIds;
    for (size_t i = 0; i < planes.size(); ++i) {
        const std::string path = "planes[" + std::to_string(i) + "]";
        doc.planes.push_back(planeFromJson(planes[i], path));
        if (doc.planes.back().id == 0) doc.planes.back().id = static_cast<int>(i) + 1;
        if (!planeIds.insert(doc.planes.back().id).second) throw io::InputError(path + ".id: used by another plane");
        usedIds.insert(doc.planes.back().id);
    }
    const json& curves = optionalArray(j, "curves");
    for (size_t i = 0; i < curves.size(); ++i) {
        const std::string path = "curves[" + std::to_string(i) + "]";
        doc.curves.push_back(io::curveFromJson(curves[i], path));
        checkExtent(doc.curves.back().points(), path);
        int plane = 0;
        if (const auto it = curves[i].find("plane"); it != curves[i].end()) {
            plane = io::integerFromJson(*it, path + ".plane", 1, 1 << 30);
            if (!planeIds.count(plane)) throw io::InputError(path + ".plane: no plane has id " + std::to_string(plane));
            const auto& points = doc.curves.back().points();
            for (size_t k = 0; k < points.size(); ++k) {
                if (points[k].z() != 0.0) {
                    throw io::InputError(path + ".points[" + std::to_string(k) + "]: a curve on a plane has plane-local 2D points (z must be 0)");
                }
            }
        }
        doc.curvePlanes.push_back(plane);
        std::vector<int> fixed;
        if (const auto it = curves[i].find("fixed"); it != curves[i].end()) {
            if (!it->is_array()) throw io::InputError(path + ".fixed: expected an array of control point indices");
            const int count = static_cast<int>(doc.curves.back().points().size());
            for (size_t k = 0; k < it->size(); ++k)
                fixed.push_back(io::integerFromJson((*it)[k], path + ".fixed[" + std::to_string(k) + "]", 0, count - 1));
        }
        doc.curveFixed.push_back(std::move(fixed));
        doc.curveIds.push_back(entityId(curves[i], path, usedIds));
        if (doc.curveIds.back() != 0 && plane != 0 && doc.curveIds.back() < plane) {
            throw io::InputError(path + ".id: must be greater than its plane's id");
        }
    }
    const json& points = optionalArray(j, "points");
    for (size_t i = 0; i < points.size(); ++i) {
        const std::string path = "points[" + std::to_string(i) + "]";
        if (!points[i].is_object()) throw io::InputError(path + ": must be an object");
        SceneDocument::PointSpec spec;
        spec.id = entityId(points[i], path, usedIds);
        if (spec.id == 0) throw io::InputError(path + ".id: a point needs an id (sculpts name their points)");
        spec.position = io::pointFromJson(io::member(points[i], "position", path), path + ".position");
        checkExtent(spec.position, path + ".position");
        if (const auto r = points[i].find("rotation"); r != points[i].end()) {
            if (!r->is_array() || r->size() != 4) throw io::InputError(path + ".rotation: expected [x, y, z, w]");
            Eigen::Quaterniond q;
            q.x() = io::numberFromJson((*r)[0], path + ".rotation[0]");
            q.y() = io::numberFromJson((*r)[1], path + ".rotation[1]");
            q.z() = io::numberFromJson((*r)[2], path + ".rotation[2]");
            q.w() = io::numberFromJson((*r)[3], path + ".rotation[3]");
            if (q.norm() < 1e-6) throw io::InputError(path + ".rotation: not a rotation (a zero quaternion)");
            spec.rotation = q.normalized();
        }
        doc.points.push_back(spec);
    }
    const json& surfaces = optionalArray(j, "surfaces");
    for (size_t i = 0; i < surfaces.size(); ++i) {
        const std::string path = "surfaces[" + std::to_string(i) + "]";
        const int id = entityId(surfaces[i], path, usedIds);
        if (auto constructed = constructionFromJson(surfaces[i], path, id, doc)) {
            doc.constructed.push_back(std::move(*constructed));
            continue;
        }
        doc.surfaces.push_back(io::surfaceFromJson(surfaces[i], path));
        checkExtent(doc.surfaces.back().points(), path);
        doc.surfaceIds.push_back(id);
        const auto k = surfaces[i].find("incidence_k");
        doc.surfaceIncidenceK.push_back(k == surfaces[i].end() ? 0 : io::integerFromJson(*k, path + ".incidence_k", 0, 1 << 20));
        std::optional<solvers::Surface3d> prior;
        if (const auto p = surfaces[i].find("incidence_prior"); p != surfaces[i].end()) {
            prior = io::surfaceFromJson(*p, path + ".incidence_prior");
            const solvers::Surface3d& s = doc.surfaces.back();
            if (prior->degreeU() != s.degreeU() || prior->degreeV() != s.degreeV() || prior->knotsU() != s.knotsU() ||
                prior->knotsV() != s.knotsV() || prior->countU() != s.countU() || prior->countV() != s.countV() ||
                prior->isRational() != s.isRational())
                throw io::InputError(path + ".incidence_prior: must have the surface's degrees, knots and control point counts");
            checkExtent(prior->points(), path + ".incidence_prior");
        }
        doc.surfacePriors.push_back(std::move(prior));
    }
    const json& meshes = optionalArray(j, "meshes");
    for (size_t i = 0; i < meshes.size(); ++i) {
        const std::string path = "meshes[" + std::to_string(i) + "]";
        if (!meshes[i].is_object()) throw io::InputError(path + ": must be an object");
        SceneDocument::MeshSpec spec;
        spec.id = entityId(meshes[i], path, usedIds);
        const json& curves = io::member(meshes[i], "curves", path);
        if (!curves.is_array() || curves.empty()) throw io::InputError(path + ".curves: expected a loop of curve ids");
        for (size_t k = 0; k < curves.size(); ++k) {
            const std::string field = path + ".curves[" + std::to_string(k) + "]";
            const int id = io::integerFromJson(curves[k], field, 1, 1 << 30);
            if (std::find(doc.curveIds.begin(), doc.curveIds.end(), id) == doc.curveIds.end())
                throw io::InputError(field + ": no curve has id " + std::to_string(id));
            if (spec.id != 0 && id >= spec.id) throw io::InputError(field + ": must be smaller than the mesh's id");
            spec.curves.push_back(id);
        }
        doc.meshes.push_back(std::move(spec));
    }
    readSolids(j, doc, usedIds);
    const json& constraints = optionalArray(j, "constraints");
    // The kind of every entity the document names, for the constraints' checks.
    std::map<int, EntityKind> kinds;
    for (const PlaneSpec& p : doc.planes) kinds[p.id] = EntityKind::Plane;
    for (int id : doc.curveIds) kinds[id] = EntityKind::Curve;
    for (int id : doc.surfaceIds) kinds[id] = EntityKind::Surface;
    for (const SceneDocument::ConstructedSurface& c : doc.constructed) kinds[c.id] = EntityKind::Surface;
    for (const SceneDocument::MeshSpec& m : doc.meshes) kinds[m.id] = EntityKind::Mesh;
    for (const SceneDocument::PointSpec& p : doc.points) kinds[p.id] = EntityKind::Point;
    kinds.erase(0);  // entities without an id cannot be named
    auto entityList = [&](const json& c, const char* name, const std::string& path) {
        std::vector<int> ids;
        const auto it = c.find(name);
        if (it == c.end()) return ids;
        if (!it->is_array()) throw io::InputError(path + "." + name + ": expected an array of entity ids");
        for (size_t k = 0; k < it->size(); ++k) {
            const std::string field = path + "." + name + "[" + std::to_string(k) + "]";
            const int id = io::integerFromJson((*it)[k], field, 1, 1 << 30);
            if (!kinds.count(id)) throw io::InputError(field + ": no entity has id " + std::to_string(id));
            ids.push_back(id);
        }
        return ids;
    };
    for (size_t i = 0; i < constraints.size(); ++i) {
        const std::string path = "constraints[" + std::to_string(i) + "]";
        const json& c = constraints[i];
        if (!c.is_object()) throw io::InputError(path + ": must be an object");
        Constraint spec;
        // An id is read (older documents numbered pins with the entities) but not kept: constraints
        // are numbered apart from entities.
        entityId(c, path, usedIds);
        const json& type = io::member(c, "type", path);
        const std::optional<ConstraintType> parsed = type.is_string() ? constraintTypeFromName(type.get<std::string>()) : std::nullopt;
        if (!parsed || derivedConstraint(*parsed)) {
            throw io::InputError(path + ".type: must be \"position\", \"tangent\", \"fixed-points\", \"point-on-curve\", "
                                        "\"curve-on-surface\", \"normal\", \"g1\" or \"smoothing\"");
        }
        spec.type = *parsed;
        if (const auto curve = c.find("curve"); curve != c.end()) {
            // A pin as documents have always written it: {"curve": id, "type", "u"}.
            const int id = io::integerFromJson(*curve, path + ".curve", 1, 1 << 30);
            if (std::find(doc.curveIds.begin(), doc.curveIds.end(), id) == doc.curveIds.end() || id == 0)
                throw io::InputError(path + ".curve: no curve has id " + std::to_string(id));
            spec.targets = {static_cast<EntityId>(id)};
        } else {
            const std::vector<int> targets = entityList(c, "targets", path);
            spec.targets.assign(targets.begin(), targets.end());
        }
        const std::vector<int> sources = entityList(c, "sources", path);
        spec.sources.assign(sources.begin(), sources.end());
        if (const auto u = c.find("u"); u != c.end()) spec.parameters.push_back(io::numberFromJson(*u, path + ".u"));
        if (const auto uv = c.find("uv"); uv != c.end()) {
            if (!uv->is_array() || uv->size() != 2) throw io::InputError(path + ".uv: expected [u, v]");
            for (size_t k = 0; k < 2; ++k) spec.parameters.push_back(io::numberFromJson((*uv)[k], path + ".uv[" + std::to_string(k) + "]"));
        }
        if (const auto ix = c.find("indices"); ix != c.end()) {
            if (!ix->is_array()) throw io::InputError(path + ".indices: expected an array of indices");
            for (size_t k = 0; k < ix->size(); ++k)
                spec.indices.push_back(io::integerFromJson((*ix)[k], path + ".indices[" + std::to_string(k) + "]", 0, 1 << 20));
        }
        if (const auto v = c.find("value"); v != c.end()) spec.value = io::pointFromJson(*v, path + ".value");
        if (const auto g = c.find("preimage"); g != c.end()) {
            if (*parsed != ConstraintType::CurveOnSurface) throw io::InputError(path + ".preimage: only a curve-on-surface constraint has one");
            solvers::Curve3d domain = io::curveFromJson(*g, path + ".preimage");
            for (const Eigen::Vector3d& p : domain.points()) {
                if (p.z() != 0.0) throw io::InputError(path + ".preimage: points are [u, v, 0] in the surface's domain");
            }
            if (domain.isRational()) throw io::InputError(path + ".preimage: must not be rational");
            spec.preimage = std::move(domain);
        }
        if (const auto w = c.find("weight"); w != c.end()) {
            spec.weight = io::numberFromJson(*w, path + ".weight");
            if (!(spec.weight >= 0.0)) throw io::InputError(path + ".weight: must not be negative");
        }
        std::vector<EntityKind> targetKinds;
        for (EntityId id : spec.targets) targetKinds.push_back(kinds.at(static_cast<int>(id)));
        if (const std::string error = constraintShapeError(spec.type, targetKinds, spec.parameters.size(), spec.indices.size()); !error.empty())
            throw io::InputError(path + ": " + error);
        if (spec.type == ConstraintType::FixedPoints) {
            const size_t curve = static_cast<size_t>(
                std::find(doc.curveIds.begin(), doc.curveIds.end(), static_cast<int>(spec.targets.front())) - doc.curveIds.begin());
            const solvers::Curve3d& k = doc.curves[curve];
            const int count = k.isClosed() ? k.pointCount() - k.degree() : k.pointCount();
            for (size_t n = 0; n < spec.indices.size(); ++n) {
                if (spec.indices[n] >= count) throw io::InputError(path + ".indices[" + std::to_string(n) + "]: curve " + std::to_string(spec.targets.front()) + " has " + std::to_string(count) + " control points");
            }
        }
        doc.constraints.push_back(std::move(spec));
    }
    // Entity states ("state": "fixed"), read after everything is known.
    auto readState = [](const json& e, const std::string& path) {
        const auto it = e.find("state");
        if (it == e.end()) return false;
        if (!it->is_string() || (*it != "fixed" && *it != "free")) throw io::InputError(path + ".state: must be \"fixed\" or \"free\"");
        return *it == "fixed";
    };
    for (size_t i = 0; i < planes.size(); ++i) doc.planes[i].fixed = readState(planes[i], "planes[" + std::to_string(i) + "]");
    for (size_t i = 0; i < curves.size(); ++i) doc.curveStates.push_back(readState(curves[i], "curves[" + std::to_string(i) + "]"));
    size_t constructed = 0;
    for (size_t i = 0; i < surfaces.size(); ++i) {
        const bool fixed = readState(surfaces[i], "surfaces[" + std::to_string(i) + "]");
        if (surfaces[i].contains("construction")) doc.constructed[constructed++].fixed = fixed;
        else doc.surfaceStates.push_back(fixed);
    }
    for (size_t i = 0; i < meshes.size(); ++i) doc.meshes[i].fixed = readState(meshes[i], "meshes[" + std::to_string(i) + "]");
    for (size_t i = 0; i < points.size(); ++i) doc.points[i].fixed = readState(points[i], "points[" + std::to_string(i) + "]");
    doc.references = referencesFromJson(optionalArray(j, "references"));
    return doc;
}

namespace {

/// Far above any real document (the 20-curve benchmark scene is 40 kB; a 100 x 100 surface about
/// 1 MB), and what sculptline-cli reads at most as input.
constexpr size_t kMaxDocumentBytes = size_t{256} << 20;

}  // namespace

SceneDocument loadDocument(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw io::InputError(path + ": cannot open file");
    // Read in chunks up to a bound: a path that never ends (/dev/zero, a pipe) fails fast instead of
    // taking all memory.
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<size_t>(in.gcount()));
        if (text.size() > kMaxDocumentBytes)
            throw io::InputError(path + ": larger than " + std::to_string(kMaxDocumentBytes >> 20) + " MiB, not a document");
    }
    if (in.bad()) throw io::InputError(path + ": cannot read file");
    try {
        return documentFromJson(io::parseJson(text));
    } catch (const io::InputError& e) {
        throw io::InputError(path + ": " + e.what());
    }
}

SceneDocument freshDocument()
{
    SceneDocument doc;
    PlaneSpec plane;
    plane.origin = Eigen::Vector3d(0, 0, 60);
    plane.normal = Eigen::Vector3d(0, -1, 0);
    plane.size = kFreshPlaneSize;
    plane.id = 1;
    doc.planes.push_back(plane);
    return doc;
}

}  // namespace sculptline::model
