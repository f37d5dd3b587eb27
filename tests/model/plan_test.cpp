// The planner alone (model/plan.h): topological order of one-way recipes, strongly connected
// components for coupled constraints, fixed entities as sources, determinism, and the steps a change
// sets off.
#include "model/plan.h"

#include <gtest/gtest.h>

namespace sculptline::model {
namespace {

Constraint relation(ConstraintId id, ConstraintType type, std::vector<EntityId> sources, std::vector<EntityId> targets)
{
    Constraint c;
    c.id = id;
    c.type = type;
    c.sources = std::move(sources);
    c.targets = std::move(targets);
    return c;
}

std::vector<const Constraint*> pointers(const std::vector<Constraint>& constraints)
{
    std::vector<const Constraint*> out;
    for (const Constraint& c : constraints) out.push_back(&c);
    return out;
}

/// Names steps by their size, so tests can see clusters without a registry.
std::string bySize(const PlanStep& step) { return step.solve.size() == 1 ? "single" : "cluster"; }

TEST(Plan, OneWayRecipesComeInTopologicalOrderWhateverTheirIds)
{
    // Given a surface (2) built from a curve (5) that lies on a plane (7): ids against the order,
    // as a curve drawn later on an earlier surface would have them
    const std::vector<Constraint> c{relation(1, ConstraintType::Construction, {5}, {2}),
                                    relation(2, ConstraintType::Placement, {7}, {5})};
    // When planned
    const Plan plan = makePlan({2, 5, 7}, {}, pointers(c), bySize);
    // Then the curve is placed before the surface is built, and the plane is a source
    ASSERT_EQ(plan.steps.size(), 2u);
    EXPECT_EQ(plan.steps[0].solve, std::vector<EntityId>{5});
    EXPECT_EQ(plan.steps[0].constraints, std::vector<ConstraintId>{2});
    EXPECT_EQ(plan.steps[1].solve, std::vector<EntityId>{2});
    EXPECT_EQ(plan.stepOf.count(7), 0u);
}

TEST(Plan, CoupledFreeEntitiesFormOneClusterAndItsDependentsFollowIt)
{
    // Given a curve (3) on a surface (4) both free (a curve-on-surface couples them), the surface
    // built from curve 1, and a surface 6 built from curve 3
    const std::vector<Constraint> c{relation(1, ConstraintType::CurveOnSurface, {}, {3, 4}),
                                    relation(2, ConstraintType::Construction, {1}, {4}),
                                    relation(3, ConstraintType::Construction, {3}, {6})};
    const Plan plan = makePlan({1, 3, 4, 6}, {}, pointers(c), bySize);
    // Then 3 and 4 are solved together, under both constraints that consume their freedom, and 6 after
    ASSERT_EQ(plan.steps.size(), 2u);
    EXPECT_EQ(plan.steps[0].solve, (std::vector<EntityId>{3, 4}));
    EXPECT_EQ(plan.steps[0].solver, "cluster");
    EXPECT_EQ(plan.steps[0].constraints, (std::vector<ConstraintId>{1, 2}));
    EXPECT_EQ(plan.steps[1].solve, std::vector<EntityId>{6});
}

TEST(Plan, AFixedEntityIsNeverSolvedAndItsCouplingBecomesOneWay)
{
    // The same coupling with the surface fixed: the curve alone is solved, after nothing
    const std::vector<Constraint> c{relation(1, ConstraintType::CurveOnSurface, {}, {3, 4})};
    const Plan plan = makePlan({3, 4}, {4}, pointers(c), bySize);
    ASSERT_EQ(plan.steps.size(), 1u);
    EXPECT_EQ(plan.steps[0].solve, std::vector<EntityId>{3});
    EXPECT_EQ(plan.stepOf.count(4), 0u);
}

TEST(Plan, SeedFigureThreeOrdersTheCrossingPointsThenCurveBThenTheSurface)
{
    // Seed 000 Fig. 3: A (1) fixed; P1 (3) and P2 (4) on A and on B (2); S (5) through A and B.
    const std::vector<Constraint> c{relation(1, ConstraintType::PointOnCurve, {1}, {3}), relation(2, ConstraintType::PointOnCurve, {1}, {4}),
                                    relation(3, ConstraintType::PointOnCurve, {3}, {2}), relation(4, ConstraintType::PointOnCurve, {4}, {2}),
                                    relation(5, ConstraintType::CurveOnSurface, {1}, {5}), relation(6, ConstraintType::CurveOnSurface, {2}, {5})};
    const Plan plan = makePlan({1, 2, 3, 4, 5}, {1}, pointers(c), bySize);
    // Fig. 3(b): A fixed enforces P1 and P2, they constrain B, and S comes last from A and B
    ASSERT_EQ(plan.steps.size(), 4u);
    EXPECT_EQ(plan.steps[0].solve, std::vector<EntityId>{3});
    EXPECT_EQ(plan.steps[1].solve, std::vector<EntityId>{4});
    EXPECT_EQ(plan.steps[2].solve, std::vector<EntityId>{2});
    EXPECT_EQ(plan.steps[2].constraints, (std::vector<ConstraintId>{3, 4}));
    EXPECT_EQ(plan.steps[3].solve, std::vector<EntityId>{5});
    EXPECT_EQ(plan.steps[3].constraints, (std::vector<ConstraintId>{5, 6}));
}

TEST(Plan, ALongChainOfRecipesIsPlannedWithoutRecursion)
{
    // 100,000 recipes in a chain (a recursive Tarjan would overflow the stack here)
    constexpr EntityId kCount = 100000;
    std::vector<Constraint> c;
    std::vector<EntityId> ids{1};
    for (EntityId i = 2; i <= kCount; ++i) {
        c.push_back(relation(i, ConstraintType::Construction, {i - 1}, {i}));
        ids.push_back(i);
    }
    const Plan plan = makePlan(ids, {}, pointers(c), bySize);
    ASSERT_EQ(plan.steps.size(), kCount - 1);
    for (size_t k = 0; k < plan.steps.size(); ++k) ASSERT_EQ(plan.steps[k].solve.front(), k + 2);
}

TEST(Plan, StepsAfterAChangeAreItsDependentsOnlyInPlanOrder)
{
    // Two planes (1, 2) with a curve each (3 on 1, 4 on 2), a loft of both (5), a surface of 4 alone (6)
    const std::vector<Constraint> c{relation(1, ConstraintType::Placement, {1}, {3}), relation(2, ConstraintType::Placement, {2}, {4}),
                                    relation(3, ConstraintType::Construction, {3, 4}, {5}),
                                    relation(4, ConstraintType::Construction, {4}, {6})};
    const Plan plan = makePlan({1, 2, 3, 4, 5, 6}, {}, pointers(c), bySize);
    // When plane 1 moves, curve 3 and the loft follow; curve 4 and surface 6 do not
    const std::vector<size_t> run = stepsAfter(plan, {1});
    std::vector<EntityId> solved;
    for (size_t k : run) solved.push_back(plan.steps[k].solve.front());
    EXPECT_EQ(solved, (std::vector<EntityId>{3, 5}));
}

}  // namespace
}  // namespace sculptline::model
