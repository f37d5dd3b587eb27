#include "scene/iv_import.h"

#include "solvers/io/geometry_json.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/SoPath.h>
#include <Inventor/elements/SoCoordinateElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoIndexedLineSet.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoNormalBinding.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShape.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace sculptline::scene {
namespace {

using solvers::io::InputError;

/// Collects Coin's read errors (and debug warnings) while it reads, instead of its default handler
/// printing them; restores the previous handlers.
class CoinMessages {
public:
    CoinMessages()
    {
        readCb_ = SoReadError::getHandlerCallback();
        readData_ = SoReadError::getHandlerData();
        debugCb_ = SoDebugError::getHandlerCallback();
        debugData_ = SoDebugError::getHandlerData();
        SoReadError::setHandlerCallback(&CoinMessages::collect, &errors_);
        SoDebugError::setHandlerCallback(&CoinMessages::collect, &warnings_);
    }
    ~CoinMessages()
    {
        SoReadError::setHandlerCallback(readCb_, readData_);
        SoDebugError::setHandlerCallback(debugCb_, debugData_);
    }
    CoinMessages(const CoinMessages&) = delete;
    CoinMessages& operator=(const CoinMessages&) = delete;

    const std::string& errors() const { return errors_; }

private:
    static void collect(const SoError* error, void* data)
    {
        auto* out = static_cast<std::string*>(data);
        if (!out->empty()) return;  // the first message says what went wrong
        std::string text = error->getDebugString().getString();
        for (char& c : text)
            if (c == '\n' || c == '\r') c = ' ';
        *out = text.substr(0, 300);
    }

    SoErrorCB* readCb_;
    void* readData_;
    SoErrorCB* debugCb_;
    void* debugData_;
    std::string errors_, warnings_;
};

/// Removes every node of `type` below `root` (searched as paths, removed from their parents).
void removeAll(SoSeparator* root, SoType type)
{
    SoSearchAction search;
    search.setType(type);
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(root);
    const SoPathList& paths = search.getPaths();
    for (int i = 0; i < paths.getLength(); ++i) {
        const SoPath* path = paths[i];
        if (path->getLength() < 2) continue;
        auto* parent = static_cast<SoGroup*>(path->getNodeFromTail(1));
        const int at = parent->findChild(path->getTail());
        if (at >= 0) parent->removeChild(at);
    }
}

/// Normals and material bindings out, indices into them emptied: the reference is drawn grey with
/// normals Coin generates, and no index but the checked coordinate indices is followed.
void dropShading(SoSeparator* root)
{
    removeAll(root, SoNormal::getClassTypeId());
    removeAll(root, SoNormalBinding::getClassTypeId());
    removeAll(root, SoMaterialBinding::getClassTypeId());
    SoSearchAction search;
    search.setType(SoIndexedShape::getClassTypeId());
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(root);
    const SoPathList& paths = search.getPaths();
    for (int i = 0; i < paths.getLength(); ++i) {
        auto* shape = static_cast<SoIndexedShape*>(paths[i]->getTail());
        shape->normalIndex.setValue(-1);
        shape->materialIndex.setValue(-1);
        shape->textureCoordIndex.setValue(-1);
    }
}

/// The traversal that checks and counts: before each shape is drawn (a pre-callback, so Coin has
/// not followed its indices yet), its indices against the coordinates in effect; then every
/// triangle, segment and point it generates, in world coordinates.
class Census {
public:
    explicit Census(const IvLimits& limits) : limits_(limits)
    {
        action_.addPreCallback(SoShape::getClassTypeId(), &Census::checkShape, this);
        action_.addTriangleCallback(SoShape::getClassTypeId(), &Census::triangle, this);
        action_.addLineSegmentCallback(SoShape::getClassTypeId(), &Census::segment, this);
        action_.addPointCallback(SoShape::getClassTypeId(), &Census::point, this);
    }

    IvGeometryCensus run(SoNode* root)
    {
        action_.apply(root);
        if (!error_.empty()) throw InputError(error_);
        if (census_.triangles + census_.segments + census_.points == 0) throw InputError("nothing to draw (no shape with vertices)");
        return census_;
    }

private:
    static SoCallbackAction::Response checkShape(void* self, SoCallbackAction* action, const SoNode* node)
    {
        auto* c = static_cast<Census*>(self);
        if (!c->error_.empty()) return SoCallbackAction::ABORT;
        c->error_ = c->shapeProblem(action, node);
        return c->error_.empty() ? SoCallbackAction::CONTINUE : SoCallbackAction::ABORT;
    }

    std::string shapeProblem(SoCallbackAction* action, const SoNode* node) const
    {
        const long long coords = SoCoordinateElement::getInstance(action->getState())->getNum();
        const std::string type = node->getTypeId().getName().getString();
        auto past = [&](const char* field, long long value) {
            return std::string(field) + " " + std::to_string(value) + " of " + type + " is past its " + std::to_string(coords) + " coordinates";
        };
        if (node->isOfType(SoIndexedShape::getClassTypeId())) {
            const auto* shape = static_cast<const SoIndexedShape*>(node);
            const int n = shape->coordIndex.getNum();
            const int32_t* index = shape->coordIndex.getValues(0);
            // Coin 4.0.0 crashes on a FaceSet face of fewer than 3 vertices, and its IndexedLineSet
            // makes a segment of a 1-vertex line: every face and line must have enough vertices.
            const int least = node->isOfType(SoIndexedFaceSet::getClassTypeId()) ? 3 : 2;
            int run = 0, runs = 0;
            for (int i = 0; i <= n; ++i) {
                if (i == n || index[i] == -1) {
                    if (i == n && run == 0) break;  // ended by its -1, or empty
                    ++runs;
                    if (run < least)
                        return (least == 3 ? "face " : "line ") + std::to_string(runs) + " of " + type + " has " + std::to_string(run) +
                               " vertices (" + std::to_string(least) + " or more needed)";
                    run = 0;
                    continue;
                }
                if (index[i] < -1) return "coordIndex " + std::to_string(index[i]) + " of " + type + " is negative";
                if (index[i] >= coords) return past("coordIndex", index[i]);
                ++run;
            }
        } else if (node->isOfType(SoPointSet::getClassTypeId())) {
            const auto* set = static_cast<const SoPointSet*>(node);
            const long long start = set->startIndex.getValue(), count = set->numPoints.getValue();
            if (start < 0) return "startIndex of " + type + " is negative";
            if (count < -1) return "numPoints of " + type + " is negative";
            if (start + std::max(count, 0LL) > coords) return past("startIndex + numPoints", start + count);
        } else if (node->isOfType(SoFaceSet::getClassTypeId()) || node->isOfType(SoLineSet::getClassTypeId())) {
            const auto* shape = static_cast<const SoNonIndexedShape*>(node);
            const SoMFInt32& counts = node->isOfType(SoFaceSet::getClassTypeId()) ? static_cast<const SoFaceSet*>(node)->numVertices
                                                                                    : static_cast<const SoLineSet*>(node)->numVertices;
            const long long least = node->isOfType(SoFaceSet::getClassTypeId()) ? 3 : 2;  // a FaceSet face of 1 or 2 crashes Coin 4.0.0
            long long used = shape->startIndex.getValue();
            if (used < 0) return "startIndex of " + type + " is negative";
            for (int i = 0; i < counts.getNum(); ++i) {
                const long long v = counts[i];
                if (v == -1 && i == counts.getNum() - 1) {  // SO_FACE_SET_USE_REST_OF_VERTICES
                    if (coords - used < least) return "the last numVertices (-1) of " + type + " leaves " + std::to_string(coords - used) + " vertices";
                    break;
                }
                if (v < least) return "numVertices " + std::to_string(v) + " of " + type + " must be " + std::to_string(least) + " or more (or -1 last)";
                used += v;
                if (used > coords) return past("numVertices up to", used);
            }
        }
        return {};
    }

    /// A drawn vertex in world coordinates: finite, within the limit; grows the box.
    void vertex(SoCallbackAction* action, const SoPrimitiveVertex* v)
    {
        SbVec3f world;
        action->getModelMatrix().multVecMatrix(v->getPoint(), world);
        for (int k = 0; k < 3; ++k) {
            const double x = world[k];
            if (!std::isfinite(x)) {
                error_ = "a vertex is not finite after the transforms (a degenerate Rotation, Scale or MatrixTransform?)";
                return;
            }
            if (std::abs(x) > limits_.maxCoordinate) {
                char text[64];
                std::snprintf(text, sizeof text, "%g", x);
                error_ = "a vertex at " + std::string(text) + " model units is outside +-1e6 (after the transforms)";
                return;
            }
            if (first_) census_.min[k] = census_.max[k] = x;
            census_.min[k] = std::min(census_.min[k], x);
            census_.max[k] = std::max(census_.max[k], x);
        }
        first_ = false;
    }

    bool overBudget()
    {
        if (!error_.empty()) return true;
        if (census_.triangles + census_.segments + census_.points > limits_.maxPrimitives) {
            error_ = "more than " + std::to_string(limits_.maxPrimitives) + " triangles, segments and points to draw";
            return true;
        }
        return false;
    }

    static void triangle(void* self, SoCallbackAction* action, const SoPrimitiveVertex* a, const SoPrimitiveVertex* b, const SoPrimitiveVertex* c)
    {
        auto* census = static_cast<Census*>(self);
        if (census->overBudget()) return;
        ++census->census_.triangles;
        for (const SoPrimitiveVertex* v : {a, b, c}) census->vertex(action, v);
    }
    static void segment(void* self, SoCallbackAction* action, const SoPrimitiveVertex* a, const SoPrimitiveVertex* b)
    {
        auto* census = static_cast<Census*>(self);
        if (census->overBudget()) return;
        ++census->census_.segments;
        for (const SoPrimitiveVertex* v : {a, b}) census->vertex(action, v);
    }
    static void point(void* self, SoCallbackAction* action, const SoPrimitiveVertex* a)
    {
        auto* census = static_cast<Census*>(self);
        if (census->overBudget()) return;
        ++census->census_.points;
        census->vertex(action, a);
    }

    const IvLimits& limits_;
    SoCallbackAction action_;
    IvGeometryCensus census_;
    bool first_ = true;
    std::string error_;
};

}  // namespace

ImportedIv importIvText(std::string_view text, const IvLimits& limits)
{
    ImportedIv result;
    result.text = validateIvText(text, limits);
    SoDB::init();
    // Coin reads from a copy that ends in a line break (its reader looks one character ahead).
    std::string buffer(text);
    buffer += '\n';
    SoSeparator* root = nullptr;
    {
        CoinMessages messages;
        SoInput input;
        input.setBuffer(buffer.data(), buffer.size());
        root = SoDB::readAll(&input);
        if (root) root->ref();
        if (!messages.errors().empty() || !root) {
            if (root) root->unref();
            throw InputError("Coin cannot read it: " + (messages.errors().empty() ? std::string("read failed") : messages.errors()));
        }
    }
    result.root = std::shared_ptr<SoSeparator>(root, [](SoSeparator* node) { node->unref(); });
    dropShading(root);
    CoinMessages quiet;  // Coin's warnings during the census (degenerate faces) stay off stderr
    result.geometry = Census(limits).run(root);
    return result;
}

ImportedIv importIvFile(const std::string& path, const IvLimits& limits)
{
    try {
        struct stat info {};
        if (::stat(path.c_str(), &info) != 0) throw InputError(std::string("cannot open file (") + std::strerror(errno) + ")");
        if (!S_ISREG(info.st_mode)) throw InputError("not a regular file");
        if (static_cast<unsigned long long>(info.st_size) > limits.maxBytes)
            throw InputError(std::to_string(info.st_size) + " bytes, over the limit of " + std::to_string(limits.maxBytes) + " bytes");
        std::ifstream in(path, std::ios::binary);
        if (!in) throw InputError(std::string("cannot open file (") + std::strerror(errno) + ")");
        std::string text;
        text.resize(static_cast<std::size_t>(info.st_size));
        in.read(text.data(), static_cast<std::streamsize>(text.size()));
        text.resize(static_cast<std::size_t>(in.gcount()));
        return importIvText(text, limits);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
}

std::string describe(const ImportedIv& imported)
{
    const IvGeometryCensus& g = imported.geometry;
    std::ostringstream out;
    out << imported.text.coordinates << " coordinates, " << g.triangles << " triangles";
    if (g.segments) out << ", " << g.segments << " segments";
    if (g.points) out << ", " << g.points << " points";
    out.precision(4);
    out << "; box " << g.max[0] - g.min[0] << " x " << g.max[1] - g.min[1] << " x " << g.max[2] - g.min[2];
    return out.str();
}

}  // namespace sculptline::scene
