#include "model/plan.h"

#include <algorithm>
#include <functional>
#include <queue>

namespace sculptline::model {

namespace {

/// The graph the planner orders: an edge a -> b when b cannot be solved before a.
struct Graph {
    std::vector<EntityId> nodes;                 ///< the entities some constraint solves, ascending
    std::map<EntityId, size_t> index;            ///< entity -> node
    std::vector<std::vector<size_t>> out;        ///< sorted, unique
};

void addEdge(Graph& g, size_t from, size_t to)
{
    if (from != to) g.out[from].push_back(to);
}

/// Tarjan's strongly connected components, iterative (a long chain of recipes must not overflow the
/// stack). Returns each node's component.
std::vector<size_t> components(const Graph& g, size_t& count)
{
    const size_t n = g.nodes.size();
    constexpr size_t kUnvisited = static_cast<size_t>(-1);
    std::vector<size_t> order(n, kUnvisited), low(n, 0), component(n, kUnvisited);
    std::vector<bool> onStack(n, false);
    std::vector<size_t> stack;
    size_t counter = 0;
    count = 0;
    for (size_t root = 0; root < n; ++root) {
        if (order[root] != kUnvisited) continue;
        // (node, next edge to look at)
        std::vector<std::pair<size_t, size_t>> frames{{root, 0}};
        order[root] = low[root] = counter++;
        stack.push_back(root);
        onStack[root] = true;
        while (!frames.empty()) {
            auto& [v, edge] = frames.back();
            if (edge < g.out[v].size()) {
                const size_t w = g.out[v][edge++];
                if (order[w] == kUnvisited) {
                    order[w] = low[w] = counter++;
                    stack.push_back(w);
                    onStack[w] = true;
                    frames.push_back({w, 0});
                } else if (onStack[w]) {
                    low[v] = std::min(low[v], order[w]);
                }
                continue;
            }
            if (low[v] == order[v]) {
                size_t w;
                do {
                    w = stack.back();
                    stack.pop_back();
                    onStack[w] = false;
                    component[w] = count;
                } while (w != v);
                ++count;
            }
            const size_t finished = v;
            frames.pop_back();
            if (!frames.empty()) low[frames.back().first] = std::min(low[frames.back().first], low[finished]);
        }
    }
    return component;
}

}  // namespace

Plan makePlan(const std::vector<EntityId>& entities, const std::set<EntityId>& fixed,
              const std::vector<const Constraint*>& constraints, const SolverChooser& chooseSolver)
{
    const std::set<EntityId> known(entities.begin(), entities.end());
    auto solvable = [&](EntityId e) { return known.count(e) != 0 && fixed.count(e) == 0; };
    // A placement maps a curve's own shape into the world and consumes none of its freedom: it
    // applies to a fixed curve too (whose shape stays, and whose plane may move).
    auto solves = [&](const Constraint& c, EntityId t) {
        if (!known.count(t)) return false;
        return solvable(t) || (describe(c.type).oneWay && describe(c.type).dofPerUse == 0);
    };
    // Nodes: the free entities some constraint consumes freedom of.
    Graph g;
    std::set<EntityId> solved;
    for (const Constraint* c : constraints) {
        for (EntityId t : c->targets) {
            if (solves(*c, t)) solved.insert(t);
        }
    }
    g.nodes.assign(solved.begin(), solved.end());
    for (size_t i = 0; i < g.nodes.size(); ++i) g.index[g.nodes[i]] = i;
    g.out.resize(g.nodes.size());
    for (const Constraint* c : constraints) {
        std::vector<size_t> free;
        for (EntityId t : c->targets) {
            if (solves(*c, t)) free.push_back(g.index.at(t));
        }
        // What it reads, and the targets it cannot change (fixed ones), come before what it solves.
        std::vector<EntityId> before = c->sources;
        for (EntityId t : c->targets) {
            if (!solves(*c, t)) before.push_back(t);
        }
        for (EntityId s : before) {
            const auto it = g.index.find(s);
            if (it == g.index.end()) continue;  // a source nothing solves: it is just there
            for (size_t t : free) addEdge(g, it->second, t);
        }
        // A coupling constraint ties its free targets both ways: they are solved together.
        if (!describe(c->type).oneWay) {
            for (size_t a : free) {
                for (size_t b : free) addEdge(g, a, b);
            }
        }
    }
    for (std::vector<size_t>& edges : g.out) {
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    }

    size_t count = 0;
    const std::vector<size_t> component = components(g, count);
    // Kahn's order on the components, smallest member id first among the ready ones.
    std::vector<std::vector<size_t>> members(count);
    for (size_t v = 0; v < g.nodes.size(); ++v) members[component[v]].push_back(v);
    std::vector<std::set<size_t>> next(count);
    std::vector<int> incoming(count, 0);
    for (size_t v = 0; v < g.nodes.size(); ++v) {
        for (size_t w : g.out[v]) {
            if (component[v] != component[w] && next[component[v]].insert(component[w]).second) ++incoming[component[w]];
        }
    }
    using Ready = std::pair<EntityId, size_t>;  // (smallest member id, component)
    std::priority_queue<Ready, std::vector<Ready>, std::greater<Ready>> ready;
    for (size_t k = 0; k < count; ++k) {
        if (incoming[k] == 0) ready.push({g.nodes[members[k].front()], k});
    }
    Plan plan;
    while (!ready.empty()) {
        const size_t k = ready.top().second;
        ready.pop();
        PlanStep step;
        for (size_t v : members[k]) step.solve.push_back(g.nodes[v]);
        std::sort(step.solve.begin(), step.solve.end());
        const std::set<EntityId> in(step.solve.begin(), step.solve.end());
        for (const Constraint* c : constraints) {
            if (std::any_of(c->targets.begin(), c->targets.end(), [&](EntityId t) { return in.count(t) != 0 && solves(*c, t); }))
                step.constraints.push_back(c->id);
        }
        std::sort(step.constraints.begin(), step.constraints.end());
        step.solver = chooseSolver(step);
        for (EntityId e : step.solve) plan.stepOf[e] = plan.steps.size();
        plan.steps.push_back(std::move(step));
        for (size_t m : next[k]) {
            if (--incoming[m] == 0) ready.push({g.nodes[members[m].front()], m});
        }
    }
    return plan;
}

std::vector<size_t> stepsAfter(const Plan& plan, const std::map<EntityId, std::set<ConstraintId>>& constraintsOn,
                               const std::map<ConstraintId, Constraint>& constraints, const std::set<EntityId>& changed)
{
    std::set<size_t> run;
    std::vector<EntityId> frontier(changed.begin(), changed.end());
    std::set<EntityId> seen(changed.begin(), changed.end());
    auto reach = [&](EntityId e) {
        if (seen.insert(e).second) frontier.push_back(e);
    };
    while (!frontier.empty()) {
        const EntityId e = frontier.back();
        frontier.pop_back();
        if (const auto s = plan.stepOf.find(e); s != plan.stepOf.end() && run.insert(s->second).second) {
            for (EntityId other : plan.steps[s->second].solve) reach(other);
        }
        const auto t = constraintsOn.find(e);
        if (t == constraintsOn.end()) continue;
        for (ConstraintId id : t->second) {
            const auto c = constraints.find(id);
            if (c == constraints.end()) continue;
            for (EntityId target : c->second.targets) {
                if (plan.stepOf.count(target)) reach(target);
            }
        }
    }
    return std::vector<size_t>(run.begin(), run.end());
}

}  // namespace sculptline::model
