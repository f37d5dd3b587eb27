#include "scene/iv_validate.h"

#include "solvers/io/geometry_json.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace sculptline::scene {
namespace {

using solvers::io::InputError;

/// Values drawn for a primitive shape (Cube, Sphere, ..) in the instancing budget: Coin 4.0.0
/// tessellates a Sphere at object-space complexity 1 into 1,680 triangles (390 at the default).
constexpr double kPrimitiveShapeValues = 4096.0;
/// Longest name or number token: identifiers of the allow-list are under 30 characters, a double
/// written in full under 30.
constexpr std::size_t kMaxTokenLength = 64;

enum class Kind { Float, Int, UShort, Bool, Enum, BitMask, Vec3, Rotation, Matrix, Color, MFloat, MInt, MIndex, MVec3, MColor, Node };

struct FieldSpec {
    const char* name;
    Kind kind;
    std::vector<std::string_view> words;  ///< Enum and BitMask values
};

struct NodeSpec {
    bool group = false;
    bool shape = false;  ///< a primitive shape (Cube, Sphere, Cone, Cylinder)
    bool coordinates = false;  ///< its MVec3 field counts as coordinates (Coordinate3)
    std::vector<FieldSpec> fields;
};

const std::vector<std::string_view> kCaching{"ON", "OFF", "AUTO"};
const std::vector<std::string_view> kBinding{"DEFAULT",  "OVERALL",    "PER_PART",          "PER_PART_INDEXED", "PER_FACE",
                                             "PER_FACE_INDEXED", "PER_VERTEX", "PER_VERTEX_INDEXED", "NONE"};

/// The allow-list: Coin 4.0.0's fields of each node (SoSeparator.h, SoTransform.h, ..), minus the
/// ones that name files. vertexProperty (a node in a field) is known only to refuse it by name.
const std::map<std::string_view, NodeSpec>& nodeSpecs()
{
    static const std::vector<FieldSpec> kIndexed{{"coordIndex", Kind::MIndex, {}},
                                                 {"materialIndex", Kind::MIndex, {}},
                                                 {"normalIndex", Kind::MIndex, {}},
                                                 {"textureCoordIndex", Kind::MIndex, {}},
                                                 {"vertexProperty", Kind::Node, {}}};
    static const std::vector<FieldSpec> kNonIndexed{
        {"startIndex", Kind::Int, {}}, {"numVertices", Kind::MInt, {}}, {"vertexProperty", Kind::Node, {}}};
    static const std::map<std::string_view, NodeSpec> specs{
        {"Separator",
         {true, false, false,
          {{"renderCaching", Kind::Enum, kCaching},
           {"boundingBoxCaching", Kind::Enum, kCaching},
           {"renderCulling", Kind::Enum, kCaching},
           {"pickCulling", Kind::Enum, kCaching}}}},
        {"Group", {true, false, false, {}}},
        {"TransformSeparator", {true, false, false, {}}},
        {"Transform",
         {false, false, false,
          {{"translation", Kind::Vec3, {}},
           {"rotation", Kind::Rotation, {}},
           {"scaleFactor", Kind::Vec3, {}},
           {"scaleOrientation", Kind::Rotation, {}},
           {"center", Kind::Vec3, {}}}}},
        {"Translation", {false, false, false, {{"translation", Kind::Vec3, {}}}}},
        {"Rotation", {false, false, false, {{"rotation", Kind::Rotation, {}}}}},
        {"RotationXYZ", {false, false, false, {{"axis", Kind::Enum, {"X", "Y", "Z"}}, {"angle", Kind::Float, {}}}}},
        {"Scale", {false, false, false, {{"scaleFactor", Kind::Vec3, {}}}}},
        {"MatrixTransform", {false, false, false, {{"matrix", Kind::Matrix, {}}}}},
        {"Coordinate3", {false, false, true, {{"point", Kind::MVec3, {}}}}},
        {"Normal", {false, false, false, {{"vector", Kind::MVec3, {}}}}},
        {"NormalBinding", {false, false, false, {{"value", Kind::Enum, kBinding}}}},
        {"MaterialBinding", {false, false, false, {{"value", Kind::Enum, kBinding}}}},
        {"Material",
         {false, false, false,
          {{"ambientColor", Kind::MColor, {}},
           {"diffuseColor", Kind::MColor, {}},
           {"specularColor", Kind::MColor, {}},
           {"emissiveColor", Kind::MColor, {}},
           {"shininess", Kind::MFloat, {}},
           {"transparency", Kind::MFloat, {}}}}},
        {"BaseColor", {false, false, false, {{"rgb", Kind::MColor, {}}}}},
        {"DrawStyle",
         {false, false, false,
          {{"style", Kind::Enum, {"FILLED", "LINES", "POINTS", "INVISIBLE"}},
           {"pointSize", Kind::Float, {}},
           {"lineWidth", Kind::Float, {}},
           {"linePattern", Kind::UShort, {}}}}},
        {"ShapeHints",
         {false, false, false,
          {{"vertexOrdering", Kind::Enum, {"UNKNOWN_ORDERING", "CLOCKWISE", "COUNTERCLOCKWISE"}},
           {"shapeType", Kind::Enum, {"UNKNOWN_SHAPE_TYPE", "SOLID"}},
           {"faceType", Kind::Enum, {"UNKNOWN_FACE_TYPE", "CONVEX"}},
           {"creaseAngle", Kind::Float, {}}}}},
        {"Complexity",
         {false, false, false,
          // SCREEN_SPACE is refused: its tessellation grows with the zoom (one Sphere seen close at
          // value 1 is 28,320 triangles in Coin 4.0.0), beyond any budget counted here.
          {{"type", Kind::Enum, {"OBJECT_SPACE", "BOUNDING_BOX"}},
           {"value", Kind::Float, {}},
           {"textureQuality", Kind::Float, {}}}}},
        {"LightModel", {false, false, false, {{"model", Kind::Enum, {"BASE_COLOR", "PHONG"}}}}},
        {"IndexedFaceSet", {false, false, false, kIndexed}},
        {"IndexedLineSet", {false, false, false, kIndexed}},
        {"FaceSet", {false, false, false, kNonIndexed}},
        {"LineSet", {false, false, false, kNonIndexed}},
        {"PointSet",
         {false, false, false, {{"startIndex", Kind::Int, {}}, {"numPoints", Kind::Int, {}}, {"vertexProperty", Kind::Node, {}}}}},
        {"Cube", {false, true, false, {{"width", Kind::Float, {}}, {"height", Kind::Float, {}}, {"depth", Kind::Float, {}}}}},
        {"Sphere", {false, true, false, {{"radius", Kind::Float, {}}}}},
        {"Cone",
         {false, true, false,
          {{"parts", Kind::BitMask, {"SIDES", "BOTTOM", "ALL"}}, {"bottomRadius", Kind::Float, {}}, {"height", Kind::Float, {}}}}},
        {"Cylinder",
         {false, true, false,
          {{"parts", Kind::BitMask, {"SIDES", "TOP", "BOTTOM", "ALL"}}, {"radius", Kind::Float, {}}, {"height", Kind::Float, {}}}}},
    };
    return specs;
}

/// Node types that are refused with a reason of their own (the rest: "not an accepted node type").
std::string refusalReason(std::string_view type)
{
    static const std::set<std::string_view> files{"File", "Texture2", "Texture3", "Image", "ImageArea", "SceneTexture2", "Text3",
                                                  "Text2", "AsciiText", "Font", "FontStyle", "ShaderProgram", "VertexShader",
                                                  "FragmentShader", "GeometryShader", "ShaderObject"};
    static const std::set<std::string_view> proto{"PROTO", "EXTERNPROTO", "ROUTE", "Inline", "WWWInline", "WWWAnchor"};
    if (type.size() > 2 && type.substr(0, 2) == "So" && std::isupper(static_cast<unsigned char>(type[2]))) type.remove_prefix(2);
    if (files.count(type)) return "node " + std::string(type) + " is not accepted: it reads files, fonts or shaders";
    if (proto.count(type)) return std::string(type) + " is not accepted: external references and prototypes are refused";
    if (type.size() >= 6 && type.substr(type.size() - 6) == "Engine") return "engine " + std::string(type) + " is not accepted";
    return "node type " + std::string(type) + " is not accepted (only plain geometry and property nodes)";
}

struct Token {
    enum Type { End, Name, Number, Punct } type = End;
    std::string_view text;
    int line = 1;
};

class Validator {
public:
    Validator(std::string_view text, const IvLimits& limits) : text_(text), limits_(limits) {}

    IvTextCensus run()
    {
        checkHeader();
        advance();
        double total = 0.0;
        while (token_.type != Token::End) total = addTop(total, node(0));
        census_.instancedValues = total;
        return census_;
    }

private:
    [[noreturn]] void fail(const std::string& message, int line = -1) const
    {
        throw InputError("line " + std::to_string(line < 0 ? token_.line : line) + ": " + message);
    }

    void checkHeader()
    {
        const std::size_t eol = text_.find_first_of("\r\n");
        std::string_view header = text_.substr(0, eol);
        while (!header.empty() && (header.back() == ' ' || header.back() == '\t')) header.remove_suffix(1);
        auto starts = [&](std::string_view prefix) { return header.substr(0, prefix.size()) == prefix; };
        if (header == "#Inventor V2.1 ascii" || header == "#Inventor V2.0 ascii") {
            pos_ = eol == std::string_view::npos ? text_.size() : eol;
            return;
        }
        if (starts("#Inventor") && header.find("binary") != std::string_view::npos)
            throw InputError("binary Open Inventor is not accepted: write it as ASCII (ivcat FILE > FILE-ascii.iv)");
        if (starts("#VRML")) throw InputError("VRML is not accepted: only Open Inventor V2.0/V2.1 ASCII");
        if (starts("#Inventor")) throw InputError("header \"" + std::string(header.substr(0, 40)) + "\": only Open Inventor V2.0/V2.1 ASCII is accepted");
        throw InputError("not an Open Inventor ASCII file: the first line must be \"#Inventor V2.1 ascii\"");
    }

    /// Skips white space and comments; refuses bytes no accepted token contains.
    void skipSpace()
    {
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == '\n') {
                ++line_;
                ++pos_;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++pos_;
            } else if (c == '#') {
                while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') {
                    if (text_[pos_] == '\0') fail("NUL byte in a comment (binary data)", line_);
                    ++pos_;
                }
            } else {
                return;
            }
        }
    }

    static bool nameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
    static bool nameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

    void advance()
    {
        skipSpace();
        token_ = {Token::End, {}, line_};
        if (pos_ >= text_.size()) return;
        const std::size_t start = pos_;
        const char c = text_[pos_];
        if (nameStart(c)) {
            while (pos_ < text_.size() && nameChar(text_[pos_])) ++pos_;
            token_ = {Token::Name, text_.substr(start, pos_ - start), line_};
        } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.') {
            while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.' ||
                                           text_[pos_] == '+' || text_[pos_] == '-'))
                ++pos_;
            token_ = {Token::Number, text_.substr(start, pos_ - start), line_};
        } else if (std::string_view("{}[],()|").find(c) != std::string_view::npos) {
            ++pos_;
            token_ = {Token::Punct, text_.substr(start, 1), line_};
            return;
        } else if (c == '"') {
            fail("strings are not accepted (no node of the allow-list has a text field)", line_);
        } else if (c == '=') {
            fail("field connections (=) are not accepted", line_);
        } else if (c == '\0') {
            fail("NUL byte (binary data)", line_);
        } else {
            const unsigned char u = static_cast<unsigned char>(c);
            char hex[8];
            std::snprintf(hex, sizeof hex, "0x%02X", u);
            fail(std::string("unexpected character ") + (u >= 0x20 && u < 0x7f ? std::string("'") + c + "'" : std::string(hex)), line_);
        }
        if (token_.text.size() > kMaxTokenLength) fail("a token longer than " + std::to_string(kMaxTokenLength) + " characters");
    }

    bool isPunct(char c) const { return token_.type == Token::Punct && token_.text[0] == c; }

    void expectPunct(char c, const std::string& what)
    {
        if (!isPunct(c)) fail(std::string("expected '") + c + "' " + what + ", found " + describe());
        advance();
    }

    std::string describe() const
    {
        if (token_.type == Token::End) return "the end of the file";
        return "\"" + std::string(token_.text) + "\"";
    }

    std::string_view name(const char* what)
    {
        if (token_.type != Token::Name) fail(std::string("expected ") + what + ", found " + describe());
        const std::string_view n = token_.text;
        advance();
        return n;
    }

    double number()
    {
        if (token_.type != Token::Number) fail("expected a number, found " + describe() + (token_.type == Token::Name ? " (NaN and infinity are refused)" : ""));
        std::string_view t = token_.text;
        if (!t.empty() && t[0] == '+') t.remove_prefix(1);
        double v = 0.0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (ec == std::errc::result_out_of_range) fail("number " + std::string(token_.text) + " is out of range");
        if (ec != std::errc() || end != t.data() + t.size()) fail("malformed number \"" + std::string(token_.text) + "\"");
        // Coin reads floats: beyond FLT_MAX a value is infinite there.
        if (!std::isfinite(v) || std::abs(v) > std::numeric_limits<float>::max())
            fail("number " + std::string(token_.text) + " is not a finite float");
        countNumber();
        advance();
        return v;
    }

    long long integer(long long lo, long long hi)
    {
        if (token_.type != Token::Number) fail("expected an integer, found " + describe());
        std::string_view t = token_.text;
        bool negative = false;
        if (!t.empty() && (t[0] == '+' || t[0] == '-')) {
            negative = t[0] == '-';
            t.remove_prefix(1);
        }
        int base = 10;
        if (t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) {
            base = 16;
            t.remove_prefix(2);
        }
        unsigned long long v = 0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v, base);
        if (ec != std::errc() || end != t.data() + t.size() || t.empty())
            fail("expected an integer, found " + describe() + (ec == std::errc::result_out_of_range ? " (out of range)" : ""));
        if (v > static_cast<unsigned long long>(std::numeric_limits<long long>::max())) fail("integer " + std::string(token_.text) + " is out of range");
        const long long s = negative ? -static_cast<long long>(v) : static_cast<long long>(v);
        if (s < lo || s > hi) fail("integer " + std::string(token_.text) + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        countNumber();
        advance();
        return s;
    }

    void countNumber()
    {
        if (++census_.numbers > limits_.maxNumbers) fail("more than " + std::to_string(limits_.maxNumbers) + " numbers");
    }

    /// One value of a multiple-value field; returns the numbers it holds.
    std::size_t singleValue(Kind kind)
    {
        switch (kind) {
        case Kind::MFloat: number(); return 1;
        case Kind::MInt: integer(std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()); return 1;
        case Kind::MIndex: integer(-1, std::numeric_limits<std::int32_t>::max()); return 1;
        case Kind::MVec3:
        case Kind::MColor:
            for (int i = 0; i < 3; ++i) number();
            return 3;
        default: return 0;
        }
    }

    /// A multiple-value field: one value, or [ values ] with optional commas. Returns the values.
    std::size_t multiValue(Kind kind)
    {
        std::size_t values = 0;
        if (!isPunct('[')) {
            singleValue(kind);
            return 1;
        }
        advance();
        while (!isPunct(']')) {
            if (token_.type == Token::End) fail("unterminated [ ... ] list");
            if (isPunct(',')) {
                advance();
                continue;
            }
            singleValue(kind);
            ++values;
        }
        advance();
        return values;
    }

    /// Reads the value of `field`; returns the values it counts in the instancing budget.
    std::size_t fieldValue(const FieldSpec& field, bool coordinates)
    {
        switch (field.kind) {
        case Kind::Float: number(); return 1;
        case Kind::Int: integer(std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()); return 1;
        case Kind::UShort: integer(0, 0xffff); return 1;
        case Kind::Bool: {
            if (token_.type == Token::Name && (token_.text == "TRUE" || token_.text == "FALSE")) advance();
            else integer(0, 1);
            return 1;
        }
        case Kind::Enum: {
            const int line = token_.line;
            const std::string_view word = name("an enum value");
            if (std::find(field.words.begin(), field.words.end(), word) == field.words.end())
                fail(std::string(field.name) + ": unknown value " + std::string(word), line);
            return 1;
        }
        case Kind::BitMask: {
            auto word = [&]() {
                const int line = token_.line;
                const std::string_view w = name("a mask value");
                if (std::find(field.words.begin(), field.words.end(), w) == field.words.end())
                    fail(std::string(field.name) + ": unknown value " + std::string(w), line);
            };
            if (!isPunct('(')) {
                word();
                return 1;
            }
            advance();
            word();
            while (isPunct('|')) {
                advance();
                word();
            }
            expectPunct(')', "after the mask");
            return 1;
        }
        case Kind::Vec3:
        case Kind::Color:
            for (int i = 0; i < 3; ++i) number();
            return 3;
        case Kind::Rotation:
            for (int i = 0; i < 4; ++i) number();
            return 4;
        case Kind::Matrix:
            for (int i = 0; i < 16; ++i) number();
            return 16;
        case Kind::Node:
            // Coin 4.0.0 does not even read "vertexProperty NULL" (a read error).
            fail(std::string(field.name) + " is not accepted (put the points in a Coordinate3 node)");
        case Kind::MVec3: {
            const std::size_t n = multiValue(field.kind);
            if (coordinates) {
                census_.coordinates += n;
                if (census_.coordinates > limits_.maxCoordinates)
                    fail("more than " + std::to_string(limits_.maxCoordinates) + " coordinates");
            }
            return 3 * n;
        }
        default: return multiValue(field.kind) * (field.kind == Kind::MColor ? 3 : 1);
        }
    }

    /// One node (DEF name Type { .. }, USE name, or Type { .. }); returns the values traversed when
    /// it is drawn, every USE inside it expanded.
    double node(int depth)
    {
        if (depth + 1 > limits_.maxDepth) fail("nodes nested deeper than " + std::to_string(limits_.maxDepth) + " levels");
        census_.depth = std::max(census_.depth, depth + 1);
        if (++census_.nodes > limits_.maxNodes) fail("more than " + std::to_string(limits_.maxNodes) + " nodes");
        const int line = token_.line;
        std::string_view word = name("a node");
        if (word == "USE") {
            const int useLine = token_.line;
            const std::string_view ref = name("a name after USE");
            if (std::find(open_.begin(), open_.end(), ref) != open_.end()) fail("USE " + std::string(ref) + " inside its own DEF (a cycle)", useLine);
            const auto it = defined_.find(std::string(ref));
            if (it == defined_.end()) fail("USE " + std::string(ref) + " before any DEF " + std::string(ref), useLine);
            return it->second;
        }
        std::string_view defName;
        if (word == "DEF") {
            defName = name("a name after DEF");
            word = name("a node type after the DEF name");
        }
        std::string_view type = word;
        auto& specs = nodeSpecs();
        auto spec = specs.find(type);
        if (spec == specs.end() && type.size() > 2 && type.substr(0, 2) == "So") spec = specs.find(type.substr(2));
        if (spec == specs.end()) fail(refusalReason(type), line);
        if (!defName.empty()) open_.push_back(defName);
        expectPunct('{', "after the node type " + std::string(type));
        double values = spec->second.shape ? kPrimitiveShapeValues : 0.0;
        while (!isPunct('}')) {
            if (token_.type == Token::End) fail("unterminated node " + std::string(type) + " (opened on line " + std::to_string(line) + ")");
            if (token_.type != Token::Name) fail("expected a field name or a child node in " + std::string(type) + ", found " + describe());
            const std::string_view field = token_.text;
            const auto f = std::find_if(spec->second.fields.begin(), spec->second.fields.end(),
                                        [&](const FieldSpec& s) { return field == s.name; });
            if (f != spec->second.fields.end()) {
                advance();
                values += static_cast<double>(fieldValue(*f, spec->second.coordinates));
            } else if (spec->second.group) {
                values += node(depth + 1);
            } else if (field == "fields") {
                fail("field declarations (fields [ .. ]) are not accepted");
            } else {
                fail("node " + std::string(type) + " has no field " + std::string(field) + " that is accepted");
            }
            if (values > limits_.maxInstancedValues) break;
        }
        advance();
        if (!defName.empty()) {
            open_.pop_back();
            defined_[std::string(defName)] = values;
        }
        if (values > limits_.maxInstancedValues)
            fail("over " + std::to_string(static_cast<long long>(limits_.maxInstancedValues)) + " values to draw once every USE is expanded", line);
        return values;
    }

public:
    /// Adds a top-level node's values to the instanced total, refusing past the limit.
    double addTop(double total, double values)
    {
        total += values;
        if (total > limits_.maxInstancedValues)
            fail("over " + std::to_string(static_cast<long long>(limits_.maxInstancedValues)) + " values to draw once every USE is expanded");
        return total;
    }

private:
    std::string_view text_;
    const IvLimits& limits_;
    std::size_t pos_ = 0;
    int line_ = 1;
    Token token_;
    IvTextCensus census_;
    std::vector<std::string_view> open_;  ///< DEF names whose node is being read
    std::map<std::string, double> defined_;  ///< DEF name -> values its node draws
};

}  // namespace

IvTextCensus validateIvText(std::string_view text, const IvLimits& limits)
{
    if (text.size() > limits.maxBytes)
        throw InputError(std::to_string(text.size()) + " bytes, over the limit of " + std::to_string(limits.maxBytes) + " bytes");
    return Validator(text, limits).run();
}

}  // namespace sculptline::scene
