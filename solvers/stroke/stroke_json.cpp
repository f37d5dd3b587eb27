#include "solvers/stroke/stroke_json.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/io/geometry_json.h"

#include <nlohmann/json.hpp>

namespace sculptline::solvers::stroke {
namespace {

using nlohmann::json;
using io::InputError;

std::string at(const std::string& path, size_t i) { return path + "[" + std::to_string(i) + "]"; }

std::vector<double> perPoint(const json& obj, const std::string& key, const std::string& path, size_t count)
{
    std::vector<double> out;
    if (!obj.contains(key)) return out;
    const json& a = obj[key];
    const std::string p = path + "." + key;
    if (!a.is_array()) throw InputError(p + ": must be an array");
    if (a.size() != count) {
        throw InputError(p + ": " + std::to_string(a.size()) + " values for " + std::to_string(count) + " points");
    }
    for (size_t i = 0; i < a.size(); ++i) out.push_back(io::numberFromJson(a[i], at(p, i)));
    return out;
}

}  // namespace

Stroke strokeFromJson(const json& j, const std::string& path)
{
    if (!j.is_object()) throw InputError(path + ": must be a JSON object");
    const json& pts = io::member(j, "points", path);
    if (!pts.is_array()) throw InputError(path + ".points: must be an array");
    if (pts.empty()) throw InputError(path + ".points: empty stroke, at least two distinct points are needed");
    Stroke s;
    s.points.reserve(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        const std::string p = path + ".points" + "[" + std::to_string(i) + "]";
        s.points.push_back(io::pointFromJson(pts[i], p));
        const int dim = static_cast<int>(pts[i].size());
        if (i == 0) s.dimension = dim;
        else if (dim != s.dimension) {
            throw InputError(p + ": " + std::to_string(dim) + "D point in a " + std::to_string(s.dimension) + "D stroke");
        }
    }
    s.times = perPoint(j, "times", path, pts.size());
    s.pressure = perPoint(j, "pressure", path, pts.size());
    for (size_t i = 0; i < s.pressure.size(); ++i) {
        if (s.pressure[i] < 0.0 || s.pressure[i] > 1.0) throw InputError(at(path + ".pressure", i) + ": must be in [0, 1]");
    }
    return s;
}

json toJson(const Stroke& s)
{
    json pts = json::array();
    for (const auto& p : s.points) {
        pts.push_back(s.dimension == 2 ? json::array({p.x(), p.y()}) : json::array({p.x(), p.y(), p.z()}));
    }
    json out = {{"points", pts}};
    if (!s.times.empty()) out["times"] = s.times;
    if (!s.pressure.empty()) out["pressure"] = s.pressure;
    return out;
}

namespace {

json curveJson(const Curve3d& c, int dimension)
{
    json curve = io::toJson(c);
    if (dimension == 2) {
        for (auto& p : curve["points"]) p.erase(2);
    }
    return curve;
}

}  // namespace

json recognitionToJson(const Recognition& r, int dimension)
{
    json candidates = json::array();
    for (const auto& c : r.candidates) candidates.push_back({{"kind", shapeName(c.kind)}, {"score", c.score}});
    return {{"shape", shapeName(r.kind)}, {"candidates", candidates}, {"regularized", curveJson(r.regularized, dimension)}};
}

json toJson(const UserModel& m)
{
    json nodes = json::array();
    auto link = [](int i) { return i == 0 ? json(nullptr) : json(i); };
    for (const auto& n : m.nodes()) {
        nodes.push_back({{"index", n.index}, {"name", n.name}, {"pre", link(n.preNode)}, {"curr", link(n.currNode)},
                         {"constraint", n.constraint}});
    }
    json out = {{"user", m.user()}, {"nodes", nodes}};
    if (!m.habits().empty()) {  // the shapes the user corrected (UserModel::learnShape)
        json habits = json::array();
        for (const auto& h : m.habits()) {
            json shape = json::array();
            for (const auto& p : h.shape) shape.push_back({p.x(), p.y()});
            habits.push_back({{"kind", shapeName(h.kind)}, {"shape", shape}});
        }
        out["habits"] = habits;
    }
    return out;
}

UserModel userModelFromJson(const json& j, const std::string& path)
{
    if (!j.is_object()) throw InputError(path + ": must be a JSON object");
    UserModel m;
    if (j.contains("user")) {
        if (!j["user"].is_string()) throw InputError(path + ".user: must be a string");
        m.setUser(j["user"].get<std::string>());
    }
    const json& nodes = io::member(j, "nodes", path);
    if (!nodes.is_array()) throw InputError(path + ".nodes: must be an array");
    std::vector<ChainNode> rows;
    const int n = static_cast<int>(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) {
        const std::string p = at(path + ".nodes", i);
        const json& o = nodes[i];
        ChainNode c;
        c.index = io::integerFromJson(io::member(o, "index", p), p + ".index", 1, n);
        auto link = [&](const char* key) {
            const json& v = io::member(o, key, p);
            return v.is_null() ? 0 : io::integerFromJson(v, p + "." + key, 1, n);
        };
        c.preNode = link("pre");
        c.currNode = link("curr");
        const json& name = io::member(o, "name", p);
        const json& con = io::member(o, "constraint", p);
        if (!name.is_string()) throw InputError(p + ".name: must be a string");
        if (!con.is_string()) throw InputError(p + ".constraint: must be a string");
        c.name = name.get<std::string>();
        c.constraint = con.get<std::string>();
        rows.push_back(c);
    }
    try {
        m.setNodes(std::move(rows));
    } catch (const GeometryError& e) {
        throw InputError(path + "." + e.what());
    }
    if (j.contains("habits")) {
        const json& habits = j["habits"];
        if (!habits.is_array()) throw InputError(path + ".habits: must be an array");
        for (size_t i = 0; i < habits.size(); ++i) {
            const std::string p = at(path + ".habits", i);
            const json& kind = io::member(habits[i], "kind", p);
            const json& shape = io::member(habits[i], "shape", p);
            UserModel::ShapeExample e;
            bool known = false;
            for (int k = 0; k < 10 && kind.is_string(); ++k) {
                if (kind.get<std::string>() == shapeName(static_cast<ShapeKind>(k))) {
                    e.kind = static_cast<ShapeKind>(k);
                    known = true;
                }
            }
            if (!known) throw InputError(p + ".kind: must be a shape name (\"line\" .. \"freeform\")");
            if (!shape.is_array()) throw InputError(p + ".shape: must be an array of [x, y]");
            for (size_t k = 0; k < shape.size(); ++k) {
                const std::string q = at(p + ".shape", k);
                if (!shape[k].is_array() || shape[k].size() != 2) throw InputError(q + ": must be [x, y]");
                e.shape.emplace_back(io::numberFromJson(shape[k][0], q + "[0]"), io::numberFromJson(shape[k][1], q + "[1]"));
            }
            try {
                m.addHabit(std::move(e));
            } catch (const GeometryError& err) {
                throw InputError(p + "." + err.what());
            }
        }
    }
    return m;
}

json fitResultToJson(const FitResult& r, int dimension)
{
    const json curve = curveJson(r.curve, dimension);
    return {{"curve", curve},
            {"corners", r.corners},
            {"samples", r.samples},
            {"max_error", r.maxError},
            {"tolerance", r.tolerance},
            {"closed", r.curve.isClosed()},
            {"converged", r.converged},
            {"warnings", r.warnings},
            {"dropped_samples", r.dropped},
            {"outlier_samples", r.outliers},
            {"stray", {{"distance", r.stray.distance}, {"excess", r.stray.excess}, {"after_sample", r.stray.after}}}};
}

}  // namespace sculptline::solvers::stroke
