#pragma once
// The adaptive user model of thesis §3.1.3 (Table 3-2, procedures USER MODELING and INSERT) and the
// stroke-by-stroke algorithm of Table 3-1.
#include "solvers/stroke/composite.h"

#include <string>

namespace sculptline::solvers::stroke {

/// One row of the chain table (Table 3-2). Links are row indices (1-based, 0 = NULL).
struct ChainNode {
    int index = 0;
    std::string name;        ///< "T1", .., or a composite's name ("prism", "cylinder", ...)
    int preNode = 0;         ///< the previous stroke's node
    int currNode = 0;        ///< the current stroke's node
    std::string constraint;  ///< "C1".."C6" primitives, "C7" overlap .. "C12" disjoint, or "C:<shape>"
};

/// The decision table of one user. Matching, candidate lookup and insertion are single scans:
/// O(n) in the number of nodes, as the thesis states.
class UserModel {
public:
    /// Table 3-2 as printed (T1..T12), T8 named "prism" (Fig. 3-4 a), plus the Fig. 3-4 objects
    /// cylinder and cone (circle then line, touching / inside), and the three-stroke chain of
    /// Fig. 3-4 (d) for a square profile: extrusion (square, line, C10), polygon_volume (extrusion,
    /// square, C10).
    static UserModel predefined(const std::string& user = "default");

    const std::string& user() const { return user_; }
    void setUser(std::string u) { user_ = std::move(u); }
    const std::vector<ChainNode>& nodes() const { return nodes_; }
    /// Replaces the table (loading); indices must be 1..n in order and links must point to rows.
    /// @throws GeometryError naming the offending node.
    void setNodes(std::vector<ChainNode> nodes);

    /// The row with pre == pre, curr == curr and the given constraint, or 0.
    int match(int pre, int curr, const std::string& constraint) const;
    /// The primitive row of a shape (constraint C1..C6, or a learned "C:<shape>" row), 0 if none.
    int primitiveNode(ShapeKind kind) const;
    /// Rows whose pre-node is `pre`: what the table offers after `pre` when the next stroke is
    /// ambiguous (the thesis's T8, T9, T11 after T2).
    std::vector<int> candidatesAfter(int pre) const;
    /// INSERT (P): appends a row and returns its index.
    int insert(ChainNode node);

    /// The user's drawing habits (thesis §3.1.3: the model adapts to its user). The designer said
    /// what a stroke is: `intended`, a correction when it is not recognition.kind, a confirmation
    /// when it is. The stroke's shape is remembered with that class (as ShapeExample: `samples`
    /// points evenly spaced along it, centred, in units of its extent, drawing direction kept).
    /// Confirmations count as much as corrections: without them a correction takes every later
    /// stroke near it, also those of a similar figure the recognizer read right (on the development
    /// subjects, one person's corrected curly brace took 26 of their square brackets; unistroke-report
    /// --adapt dev: +0.5 points after two strokes learned without confirmations, +1.4 with them).
    /// Does nothing when `intended` is not among the stroke's candidates.
    void learnShape(const Recognition& recognition, ShapeKind intended);
    /// A stroke resembling a remembered stroke (mean distance between corresponding samples below
    /// `options.habitDistance`, in extents; the nearest example wins) takes that example's class
    /// when it is one of its candidates: the candidate moves to the front and the regularized curve
    /// follows (when options.regularize). A nearest example of the class recognized changes nothing.
    void applyHabits(Recognition& recognition, const FitResult& fit, const RecognizeOptions& options = {}) const;
    struct ShapeExample {
        std::vector<Point2> shape;
        ShapeKind kind = ShapeKind::Freeform;
    };
    const std::vector<ShapeExample>& habits() const { return habits_; }
    /// Adds a remembered correction (loading). @throws GeometryError unless it has `samples` points.
    void addHabit(ShapeExample example);
    static constexpr int samples = 32;

private:
    std::string user_;
    std::vector<ChainNode> nodes_;
    std::vector<ShapeExample> habits_;
};

/// Table 3-2's constraint label of a relation (C7 overlap, C8 parallel, C9 vertical, C10 touch,
/// C11 inside; C12 disjoint is ours).
const char* constraintOf(Relation r);

/// One stroke as interpreted in sequence (Table 3-1).
struct Interpretation {
    Recognition recognition;        ///< STEP 2
    std::vector<Relation> relations;  ///< STEP 4, to the previous stroke (empty for the first)
    CompositeKind composite = CompositeKind::None;
    int node = 0;                   ///< the user-model row of this stroke's primitive
    int compositeNode = 0;          ///< the row matched or learned for (pre-node, this, relation)
    /// The pre-node of that row: the previous stroke's primitive row, or, for a three-stroke object,
    /// the previous stroke's composite row (Table 3-2 chains, e.g. T10 = (T9, T1, C9)); 0 for the first.
    int preNode = 0;
    bool learned = false;           ///< STEP 5 inserted a new row
    std::vector<int> offered;       ///< rows offered because the recognition was ambiguous
};

/// Runs Table 3-1 over strokes drawn one after another: each is recognized (STEP 2); from the
/// second on, its relation to the previous one is reasoned (STEP 4), the pair is matched in the
/// user model and inserted when new (STEP 5). When the previous stroke completed a composite, the
/// row (that composite, this stroke, relation) is matched first: a three-stroke object (Fig. 3-4 d,
/// composeThree; learned as such when new). A stroke is ambiguous when its two best candidates
/// score within `ambiguity`; the model's rows following the previous node are then offered. Each
/// recognition is re-ranked by the user's shape habits first (UserModel::applyHabits).
std::vector<Interpretation> interpretStrokes(const std::vector<FitResult>& fits, UserModel& model,
                                             const RecognizeOptions& options = {}, double ambiguity = 0.1);

}  // namespace sculptline::solvers::stroke
