#include "solvers/io/geometry_json.h"

#include "solvers/bspline/geometry_error.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace sculptline::solvers::io {
namespace {

using nlohmann::json;

const json& arrayMember(const json& j, const std::string& key, const std::string& path)
{
    const json& a = member(j, key, path);
    if (!a.is_array()) throw InputError(path + "." + key + ": must be an array");
    return a;
}

std::vector<double> numbers(const json& a, const std::string& path)
{
    std::vector<double> out;
    out.reserve(a.size());
    for (size_t i = 0; i < a.size(); ++i) out.push_back(numberFromJson(a[i], path + "[" + std::to_string(i) + "]"));
    return out;
}

// Geometry validation errors name the field inside the object ("knots: ..."); prefix the object's path.
template <typename F>
auto validated(const std::string& path, F&& make)
{
    try {
        return make();
    } catch (const GeometryError& e) {
        throw InputError(path + "." + e.what());
    }
}

// Finds the JSON path ("curve.points[1][0]") of the value at which parsing stopped. Used only after
// the DOM parse failed on a number that overflows a double ("1e999"), so that it is reported against
// its field like any other non-finite number; it builds nothing.
class PathLocator : public nlohmann::json_sax<json> {
public:
    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool key(string_t& k) override
    {
        frames_.back().key = k;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t, const std::string& lastToken, const json::exception&) override
    {
        token_ = lastToken;
        return false;
    }

    std::string path() const
    {
        std::string p;
        for (const Frame& f : frames_) p += f.array ? "[" + std::to_string(f.index) + "]" : (p.empty() ? "" : ".") + f.key;
        return p.empty() || p[0] == '[' ? "input" + p : p;
    }
    const std::string& token() const { return token_; }

private:
    struct Frame {
        bool array = false;
        size_t index = 0;  // arrays: index of the value being read
        std::string key;   // objects: key of the value being read
    };
    bool value()
    {
        if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
        return true;
    }
    bool open(bool array)
    {
        frames_.push_back({array, 0, {}});
        return true;
    }
    bool close()
    {
        frames_.pop_back();
        return value();  // the finished container is a value of its parent
    }

    std::vector<Frame> frames_;
    std::string token_;
};

}  // namespace

const json& member(const json& j, const std::string& key, const std::string& path)
{
    if (!j.is_object()) throw InputError(path + ": must be a JSON object");
    const auto it = j.find(key);
    if (it == j.end()) throw InputError(path + "." + key + ": missing");
    return *it;
}

std::string describeValue(const json& j)
{
    // Long enough for any valid value's name, short enough for a one-line message.
    constexpr size_t kMaxQuotedChars = 40;
    if (j.is_number() || j.is_boolean() || j.is_null()) return j.dump();
    if (j.is_string()) {
        const std::string& s = j.get_ref<const std::string&>();
        // The cut may split a UTF-8 sequence: replace it rather than throw (dump's strict default).
        return json(s.size() > kMaxQuotedChars ? s.substr(0, kMaxQuotedChars) + "..." : s)
            .dump(-1, ' ', false, json::error_handler_t::replace);
    }
    return j.type_name();
}

double numberFromJson(const json& j, const std::string& path)
{
    if (!j.is_number()) throw InputError(path + ": must be a number");
    const double v = j.get<double>();
    if (!std::isfinite(v)) throw InputError(path + ": not a finite number");
    return v;
}

int integerFromJson(const json& j, const std::string& path, int lo, int hi)
{
    if (!j.is_number_integer() && !(j.is_number_float() && std::floor(j.get<double>()) == j.get<double>())) {
        throw InputError(path + ": must be an integer");
    }
    const double v = j.get<double>();
    // A json built in code (not parsed: the parser rejects 1e999) may hold infinity, which passes the
    // integer test above; name it as what it is.
    if (!std::isfinite(v)) throw InputError(path + ": not a finite number");
    if (v < lo || v > hi) {
        throw InputError(path + ": must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " +
                         describeValue(j));
    }
    return static_cast<int>(v);
}

Eigen::Vector3d pointFromJson(const json& j, const std::string& path)
{
    if (!j.is_array() || (j.size() != 2 && j.size() != 3)) throw InputError(path + ": a point must be [x, y] or [x, y, z]");
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < j.size(); ++k) p[k] = numberFromJson(j[k], path + "[" + std::to_string(k) + "]");
    return p;
}

namespace {

// The "points" member of a curve or surface object.
std::vector<Eigen::Vector3d> controlPoints(const json& j, const std::string& path)
{
    const json& pts = arrayMember(j, "points", path);
    std::vector<Eigen::Vector3d> points;
    points.reserve(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) points.push_back(pointFromJson(pts[i], path + ".points[" + std::to_string(i) + "]"));
    return points;
}

// The optional "weights" member (absent: non-rational).
std::vector<double> optionalWeights(const json& j, const std::string& path)
{
    return j.contains("weights") ? numbers(arrayMember(j, "weights", path), path + ".weights") : std::vector<double>{};
}

}  // namespace

Curve3d curveFromJson(const json& j, const std::string& path)
{
    if (!j.is_object()) throw InputError(path + ": must be a JSON object");
    const int degree = integerFromJson(member(j, "degree", path), path + ".degree", 1, kMaxDegree);
    const std::vector<double> knots = numbers(arrayMember(j, "knots", path), path + ".knots");
    const std::vector<Eigen::Vector3d> points = controlPoints(j, path);
    const std::vector<double> weights = optionalWeights(j, path);
    bool closed = false;
    if (j.contains("closed")) {
        if (!j["closed"].is_boolean()) throw InputError(path + ".closed: must be true or false");
        closed = j["closed"].get<bool>();
    }
    return validated(path, [&] { return Curve3d(degree, knots, points, weights, closed); });
}

Surface3d surfaceFromJson(const json& j, const std::string& path)
{
    if (!j.is_object()) throw InputError(path + ": must be a JSON object");
    constexpr int kMaxCount = std::numeric_limits<int>::max() / 4;
    const int du = integerFromJson(member(j, "degreeU", path), path + ".degreeU", 1, kMaxDegree);
    const int dv = integerFromJson(member(j, "degreeV", path), path + ".degreeV", 1, kMaxDegree);
    const int cu = integerFromJson(member(j, "countU", path), path + ".countU", 1, kMaxCount);
    const int cv = integerFromJson(member(j, "countV", path), path + ".countV", 1, kMaxCount);
    const std::vector<double> ku = numbers(arrayMember(j, "knotsU", path), path + ".knotsU");
    const std::vector<double> kv = numbers(arrayMember(j, "knotsV", path), path + ".knotsV");
    const std::vector<Eigen::Vector3d> points = controlPoints(j, path);
    const std::vector<double> weights = optionalWeights(j, path);
    return validated(path, [&] { return Surface3d(du, dv, ku, kv, cu, cv, points, weights); });
}

json toJson(const Eigen::Vector3d& p)
{
    return json::array({p.x(), p.y(), p.z()});
}

json toJson(const Curve3d& c)
{
    json j;
    j["degree"] = c.degree();
    j["knots"] = c.knots();
    json pts = json::array();
    for (const auto& p : c.points()) pts.push_back(toJson(p));
    j["points"] = std::move(pts);
    if (c.isRational()) j["weights"] = c.weights();
    if (c.isClosed()) j["closed"] = true;
    return j;
}

json toJson(const Surface3d& s)
{
    json j;
    j["degreeU"] = s.degreeU();
    j["degreeV"] = s.degreeV();
    j["knotsU"] = s.knotsU();
    j["knotsV"] = s.knotsV();
    j["countU"] = s.countU();
    j["countV"] = s.countV();
    json pts = json::array();
    for (const auto& p : s.points()) pts.push_back(toJson(p));
    j["points"] = std::move(pts);
    if (s.isRational()) j["weights"] = s.weights();
    return j;
}

json parseJson(const std::string& text)
{
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        throw InputError(std::string("input: malformed JSON (") + e.what() + ")");
    } catch (const json::out_of_range&) {
        // nlohmann rejects a number that overflows a double (error 406) with no position in the tree.
        PathLocator locator;
        json::sax_parse(text, &locator);
        throw InputError(locator.path() + ": not a finite number (" + locator.token() + " overflows a double)");
    }
}

}  // namespace sculptline::solvers::io
