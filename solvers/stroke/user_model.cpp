#include "solvers/stroke/user_model.h"

#include "solvers/bspline/geometry_error.h"

#include <algorithm>

namespace sculptline::solvers::stroke {
namespace {

// C1..C6 of thesis §3.1.3: circle, triangle, line, square, rectangle, diamond.
const char* primitiveConstraint(ShapeKind k)
{
    switch (k) {
    case ShapeKind::Circle: return "C1";
    case ShapeKind::Triangle: return "C2";
    case ShapeKind::Line: return "C3";
    case ShapeKind::Square: return "C4";
    case ShapeKind::Rectangle: return "C5";
    case ShapeKind::Diamond: return "C6";
    default: return nullptr;
    }
}

}  // namespace

const char* constraintOf(Relation r)
{
    switch (r) {
    case Relation::Overlapping: return "C7";
    case Relation::Parallel: return "C8";
    case Relation::Perpendicular: return "C9";
    case Relation::Touching: return "C10";
    case Relation::Inside: return "C11";
    case Relation::Disjoint: return "C12";
    }
    return "C12";
}

UserModel UserModel::predefined(const std::string& user)
{
    UserModel m;
    m.user_ = user;
    // Table 3-2: Index, Name, Pre-Node, Curr-Node, Constraint.
    // Rows 15-16: Fig. 3-4 (d) for a square profile, a three-stroke chain (square, line touching it:
    // extrusion; then the top square touching the line: polygon volume).
    m.nodes_ = {{1, "T1", 0, 0, "C1"},  {2, "T2", 0, 0, "C2"},    {3, "T3", 0, 0, "C3"},  {4, "T4", 0, 0, "C4"},
                {5, "T5", 0, 0, "C5"},  {6, "T6", 0, 0, "C6"},    {7, "T7", 3, 4, "C8"},  {8, "prism", 2, 3, "C7"},
                {9, "T9", 2, 1, "C10"}, {10, "T10", 9, 1, "C9"},  {11, "T11", 2, 5, "C8"}, {12, "T12", 6, 6, "C7"},
                {13, "cylinder", 1, 3, "C10"}, {14, "cone", 1, 3, "C11"},
                {15, "extrusion", 4, 3, "C10"}, {16, "polygon_volume", 15, 4, "C10"}};
    return m;
}

void UserModel::setNodes(std::vector<ChainNode> nodes)
{
    const int n = static_cast<int>(nodes.size());
    for (int i = 0; i < n; ++i) {
        const ChainNode& c = nodes[i];
        const std::string at = "nodes[" + std::to_string(i) + "]";
        if (c.index != i + 1) throw GeometryError(at + ".index: must be " + std::to_string(i + 1));
        if (c.preNode < 0 || c.preNode > n) throw GeometryError(at + ".pre: no such node " + std::to_string(c.preNode));
        if (c.currNode < 0 || c.currNode > n) throw GeometryError(at + ".curr: no such node " + std::to_string(c.currNode));
        if (c.constraint.empty()) throw GeometryError(at + ".constraint: empty");
    }
    nodes_ = std::move(nodes);
}

int UserModel::match(int pre, int curr, const std::string& constraint) const
{
    for (const ChainNode& c : nodes_)
        if (c.preNode == pre && c.currNode == curr && c.constraint == constraint) return c.index;
    return 0;
}

int UserModel::primitiveNode(ShapeKind kind) const
{
    const char* c = primitiveConstraint(kind);
    const std::string label = c ? c : std::string("C:") + shapeName(kind);
    return match(0, 0, label);
}

std::vector<int> UserModel::candidatesAfter(int pre) const
{
    std::vector<int> out;
    for (const ChainNode& c : nodes_)
        if (pre != 0 && c.preNode == pre) out.push_back(c.index);
    return out;
}

int UserModel::insert(ChainNode node)
{
    node.index = static_cast<int>(nodes_.size()) + 1;
    nodes_.push_back(std::move(node));
    return nodes_.back().index;
}

namespace {

// The stroke as UserModel::samples points evenly spaced along its path (a loop: from its seam round
// to it again), centred on their mean and divided by the extent: size and position drop out,
// orientation and drawing direction stay (a person draws the same shape the same way round).
std::vector<Point2> normalizedShape(const StrokeGeometry& g)
{
    std::vector<Point2> path = g.points;
    if (g.closed) path.push_back(path.front());
    std::vector<double> arc(path.size(), 0.0);
    for (size_t i = 1; i < path.size(); ++i) arc[i] = arc[i - 1] + (path[i] - path[i - 1]).norm();
    std::vector<Point2> out;
    size_t j = 1;
    for (int k = 0; k < UserModel::samples; ++k) {
        const double s = arc.back() * k / (UserModel::samples - 1);
        while (j + 1 < path.size() && arc[j] < s) ++j;
        const double span = arc[j] - arc[j - 1], t = span > 0 ? (s - arc[j - 1]) / span : 0.0;
        out.push_back(path[j - 1] + std::clamp(t, 0.0, 1.0) * (path[j] - path[j - 1]));
    }
    Point2 c = Point2::Zero();
    for (const auto& p : out) c += p / out.size();
    const double scale = g.extent > 0 ? g.extent : 1.0;
    for (auto& p : out) p = (p - c) / scale;
    return out;
}

double meanDistance(const std::vector<Point2>& a, const std::vector<Point2>& b)
{
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i) d += (a[i] - b[i]).norm();
    return d / a.size();
}

}  // namespace

void UserModel::learnShape(const Recognition& recognition, ShapeKind intended)
{
    if (recognition.geometry.points.size() < 2) return;
    const auto& c = recognition.candidates;
    if (std::none_of(c.begin(), c.end(), [intended](const ShapeCandidate& x) { return x.kind == intended; })) return;
    habits_.push_back({normalizedShape(recognition.geometry), intended});
}

void UserModel::addHabit(ShapeExample example)
{
    if (static_cast<int>(example.shape.size()) != samples) {
        throw GeometryError("shape: must have " + std::to_string(samples) + " points, has " + std::to_string(example.shape.size()));
    }
    habits_.push_back(std::move(example));
}

void UserModel::applyHabits(Recognition& recognition, const FitResult& fit, const RecognizeOptions& options) const
{
    if (habits_.empty() || recognition.geometry.points.size() < 2) return;
    const std::vector<Point2> shape = normalizedShape(recognition.geometry);
    const ShapeExample* nearest = nullptr;
    double best = options.habitDistance;
    for (const ShapeExample& e : habits_) {
        const double d = meanDistance(shape, e.shape);
        if (d < best) {
            best = d;
            nearest = &e;
        }
    }
    if (!nearest || nearest->kind == recognition.kind) return;
    auto& c = recognition.candidates;
    const auto it = std::find_if(c.begin(), c.end(), [nearest](const ShapeCandidate& x) { return x.kind == nearest->kind; });
    if (it == c.end()) return;
    std::rotate(c.begin(), it, it + 1);
    recognition.kind = nearest->kind;
    if (options.regularize) recognition.regularized = regularizeAs(recognition, fit, recognition.kind);
}

std::vector<Interpretation> interpretStrokes(const std::vector<FitResult>& fits, UserModel& model,
                                             const RecognizeOptions& options, double ambiguity)
{
    std::vector<Interpretation> out;
    for (size_t i = 0; i < fits.size(); ++i) {
        Interpretation it;
        it.recognition = recognizeShape(fits[i], options);  // STEP 1-2
        model.applyHabits(it.recognition, fits[i], options);
        const ShapeKind kind = it.recognition.kind;
        it.node = model.primitiveNode(kind);
        if (it.node == 0) {  // a primitive the table does not know yet: learn it
            it.node = model.insert({0, shapeName(kind), 0, 0, std::string("C:") + shapeName(kind)});
            it.learned = true;
        }
        if (i > 0) {  // STEP 4-5
            const Interpretation& prev = out.back();
            it.relations = relate(prev.recognition, it.recognition);
            it.composite = composeShapes(prev.recognition, it.recognition, it.relations);
            // The topological relation (the last one) is the chain's constraint; parallel and
            // perpendicular take precedence as in Table 3-2 (T7, T11: C8).
            const Relation key = it.relations.front();
            const std::string constraint = constraintOf(key);
            // USER MODELING (Table 3-2): a matched composite becomes the pre-node of the next stroke
            // (P->Pre-Node = Q), so three strokes chain as (composite of the first two, third). We
            // take that chain when the geometry confirms a three-stroke object (Fig. 3-4 d,
            // composeThree): the row is matched, or learned when new. Otherwise the pair is matched.
            if (i > 1 && prev.composite != CompositeKind::None && prev.compositeNode != 0) {
                const CompositeKind three = composeThree(out[i - 2].recognition, prev.recognition, it.recognition);
                if (three != CompositeKind::None) {
                    it.composite = three;
                    it.preNode = prev.compositeNode;
                    it.compositeNode = model.match(it.preNode, it.node, constraint);
                    if (it.compositeNode == 0) {
                        it.compositeNode = model.insert({0, compositeName(three), it.preNode, it.node, constraint});
                        it.learned = true;
                    }
                }
            }
            if (it.compositeNode == 0) {
                it.preNode = prev.node;
                it.compositeNode = model.match(prev.node, it.node, constraint);
            }
            if (it.compositeNode == 0) {
                const std::string name = it.composite != CompositeKind::None ? compositeName(it.composite)
                                                                             : "T" + std::to_string(model.nodes().size() + 1);
                it.compositeNode = model.insert({0, name, prev.node, it.node, constraint});
                it.learned = true;
            }
            const auto& c = it.recognition.candidates;
            if (c.size() > 1 && c[0].score - c[1].score < ambiguity) it.offered = model.candidatesAfter(prev.node);
        }
        out.push_back(std::move(it));
    }
    return out;
}

}  // namespace sculptline::solvers::stroke
