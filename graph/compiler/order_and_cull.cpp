// Pass order (Kahn's algorithm, declaration order breaks ties, so the same graph
// always gives the same plan) and culling (scene needs forward, reachability back).
#include <algorithm>
#include <functional>
#include <queue>
#include <string>

#include "graph/compiler/steps.h"

namespace volgraph::compiler {
namespace {

// Edges as compressed rows: successors of pass p are succ[first[p] .. first[p + 1]).
struct Edges {
  std::vector<uint32_t> first;
  std::vector<uint32_t> succ;
};

// Read-after-write: producer of the version read → reader. Write-after-read: a
// reader of version v → the pass that makes version v + 1. A history slot reads what
// the last frame made: no dependency inside the frame.
template <typename Visit>
void for_each_dependency(const FlatGraph& g, Visit&& visit) {
  for (uint32_t p = 0; p < g.pass_count(); ++p) {
    for (uint32_t k = g.use_begin[p]; k < g.use_begin[p + 1]; ++k) {
      const ResourceUse& u = g.uses[k];
      if (u.direction == SlotDirection::output || u.direction == SlotDirection::history) continue;
      visit(g.writer(u.resource, u.version), p);
      if (u.direction == SlotDirection::input && u.version + 1 < g.version_count(u.resource)) {
        visit(p, g.writer(u.resource, u.version + 1));
      }
    }
  }
}

Edges build_edges(const FlatGraph& graph) {
  const size_t n = graph.pass_count();
  Edges e;
  e.first.assign(n + 1, 0);
  for_each_dependency(graph, [&](uint32_t from, uint32_t) { ++e.first[from + 1]; });
  for (size_t i = 0; i < n; ++i) e.first[i + 1] += e.first[i];
  e.succ.resize(e.first[n]);
  std::vector<uint32_t> fill(e.first.begin(), e.first.end() - 1);
  for_each_dependency(graph, [&](uint32_t from, uint32_t to) { e.succ[fill[from]++] = to; });
  return e;
}

[[noreturn]] void throw_cycle(const Graph& graph, const Edges& e, const std::vector<uint32_t>& indegree) {
  // Every pass left with indegree > 0 lies on or behind a cycle: a depth-first search
  // restricted to them finds a back edge.
  const size_t n = graph.passes.size();
  std::vector<uint8_t> colour(n, 0);  // 0 new, 1 on stack, 2 done
  std::vector<uint32_t> stack, cursor(n, 0);
  for (uint32_t start = 0; start < n; ++start) {
    if (indegree[start] == 0 || colour[start]) continue;
    stack.push_back(start);
    colour[start] = 1;
    while (!stack.empty()) {
      const uint32_t p = stack.back();
      const uint32_t end = e.first[p + 1];
      if (e.first[p] + cursor[p] == end) {
        colour[p] = 2;
        stack.pop_back();
        continue;
      }
      const uint32_t q = e.succ[e.first[p] + cursor[p]++];
      if (indegree[q] == 0 || colour[q] == 2) continue;
      if (colour[q] == 0) {
        colour[q] = 1;
        stack.push_back(q);
        continue;
      }
      std::string text;  // q is on the stack: the cycle is q … p → q
      size_t i = stack.size();
      while (stack[i - 1] != q) --i;
      for (size_t k = i - 1; k < stack.size(); ++k) text += graph.passes[stack[k]].name + " → ";
      text += graph.passes[q].name;
      throw GraphError(q, -1, "the graph has a cycle: " + text);
    }
  }
  throw GraphError(kNone, -1, "the graph has a cycle");
}

std::vector<uint32_t> topological_order(const FlatGraph& flat, const Edges& e) {
  const Graph& graph = *flat.graph;
  const size_t n = flat.pass_count();
  std::vector<uint32_t> indegree(n, 0);
  for (uint32_t q : e.succ) ++indegree[q];
  std::priority_queue<uint32_t, std::vector<uint32_t>, std::greater<>> ready;
  for (uint32_t p = 0; p < n; ++p) {
    if (indegree[p] == 0) ready.push(p);
  }
  std::vector<uint32_t> order;
  order.reserve(n);
  while (!ready.empty()) {
    const uint32_t p = ready.top();
    ready.pop();
    order.push_back(p);
    for (uint32_t i = e.first[p]; i < e.first[p + 1]; ++i) {
      if (--indegree[e.succ[i]] == 0) ready.push(e.succ[i]);
    }
  }
  if (order.size() != n) throw_cycle(graph, e, indegree);
  return order;
}

// Per version (flat index): whether it exists once passes are culled, and which
// version a reader of it really sees (a culled pass forwards its inout versions).
struct Versions {
  std::vector<uint8_t> exists;
  std::vector<uint32_t> seen;
};

Versions make_versions(const FlatGraph& g) {
  Versions v;
  v.exists.assign(g.version_writer.size(), 1);
  v.seen.resize(g.version_writer.size());
  for (uint32_t r = 0; r < g.resource_count(); ++r) {
    for (uint32_t k = 0; k < g.version_count(r); ++k) v.seen[g.version_index(r, k)] = k;
  }
  return v;
}

// Culls passes whose scene needs fail, and passes whose required inputs vanish with
// them. A culled pass forwards each inout slot: its new version is the one it got.
std::vector<uint8_t> cull_for_needs(const FlatGraph& g, const std::vector<uint32_t>& order, Versions& versions,
                                    std::vector<CulledPass>& culled) {
  const Graph& graph = *g.graph;
  std::vector<uint8_t> dead(g.pass_count(), 0);
  for (uint32_t p : order) {
    if (!needs_hold(g.pass_needs[p], g.pass_needs_any[p], graph.scene)) {
      dead[p] = 1;
      const SceneFeatures missing_any = (g.pass_needs_any[p] & graph.scene) ? 0 : g.pass_needs_any[p];
      culled.push_back({p, CullReason::scene_lacks, g.pass_needs[p] & ~graph.scene, 0, missing_any});
    }
    for (uint32_t k = g.use_begin[p]; k < g.use_begin[p + 1] && !dead[p]; ++k) {
      const ResourceUse& u = g.uses[k];
      if (u.direction == SlotDirection::output || u.optional) continue;
      if (versions.exists[g.version_index(u.resource, u.version)]) continue;
      dead[p] = 1;
      culled.push_back({p, CullReason::input_culled, 0, u.slot});
    }
    if (!dead[p]) continue;
    for (uint32_t k = g.use_begin[p]; k < g.use_begin[p + 1]; ++k) {
      const ResourceUse& u = g.uses[k];
      if (u.direction == SlotDirection::input || u.direction == SlotDirection::history) continue;
      if (u.direction == SlotDirection::output) {
        versions.exists[g.version_index(u.resource, 0)] = 0;
        continue;
      }
      const uint32_t from = g.version_index(u.resource, u.version);
      versions.exists[from + 1] = versions.exists[from];
      versions.seen[from + 1] = versions.seen[from];
    }
  }
  return dead;
}

// Marks live every pass a graph output depends on, following the versions readers see.
std::vector<uint8_t> reach_from_outputs(const FlatGraph& g, const Versions& versions, const std::vector<uint8_t>& dead,
                                        std::vector<uint8_t>& output_live) {
  const Graph& graph = *g.graph;
  std::vector<uint8_t> live(g.pass_count(), 0);
  std::vector<uint32_t> work;
  auto reach = [&](uint32_t r, uint32_t v) -> bool {
    const uint32_t i = g.version_index(r, v);
    if (!versions.exists[i]) return false;
    const uint32_t producer = g.writer(r, versions.seen[i]);
    if (producer == kNone) return true;  // a history: made by the last frame
    if (dead[producer]) return false;
    if (!live[producer]) {
      live[producer] = 1;
      work.push_back(producer);
    }
    return true;
  };
  output_live.assign(graph.outputs.size(), 0);
  for (size_t o = 0; o < graph.outputs.size(); ++o) {
    output_live[o] = reach(graph.outputs[o].resource, graph.outputs[o].version);
  }
  while (!work.empty()) {
    const uint32_t p = work.back();
    work.pop_back();
    for (uint32_t k = g.use_begin[p]; k < g.use_begin[p + 1]; ++k) {
      const ResourceUse& u = g.uses[k];
      if (u.direction != SlotDirection::output && u.direction != SlotDirection::history) reach(u.resource, u.version);
    }
  }
  return live;
}

}  // namespace

Schedule order_and_cull(const FlatGraph& g, bool cull) {
  const uint32_t n = g.pass_count();
  const std::vector<uint32_t> topo = topological_order(g, build_edges(g));
  Schedule s;
  s.position.assign(n, kNone);
  s.bound.assign(g.uses.size(), 0);
  std::vector<uint8_t> live(n, 1);
  Versions versions = make_versions(g);
  if (cull) {
    const std::vector<uint8_t> dead = cull_for_needs(g, topo, versions, s.culled);
    live = reach_from_outputs(g, versions, dead, s.output_live);
    for (uint32_t p = 0; p < n; ++p) {
      if (!dead[p] && !live[p]) s.culled.push_back({p, CullReason::unused, 0, 0});
    }
    std::sort(s.culled.begin(), s.culled.end(), [](const CulledPass& a, const CulledPass& b) { return a.pass < b.pass; });
  } else {
    s.output_live.assign(g.graph->outputs.size(), 1);
  }
  for (uint32_t p : topo) {
    if (!live[p]) continue;
    s.position[p] = uint32_t(s.order.size());
    s.order.push_back(p);
    for (uint32_t k = g.use_begin[p]; k < g.use_begin[p + 1]; ++k) {
      const ResourceUse& u = g.uses[k];
      s.bound[k] = u.direction == SlotDirection::output || versions.exists[g.version_index(u.resource, u.version)];
    }
  }
  return s;
}

std::vector<Lifetime> lifetimes(const FlatGraph& g, const Schedule& schedule) {
  std::vector<Lifetime> out(g.resource_count());
  for (uint32_t pos = 0; pos < schedule.order.size(); ++pos) {
    const uint32_t p = schedule.order[pos];
    for (uint32_t k = g.use_begin[p]; k < g.use_begin[p + 1]; ++k) {
      if (!schedule.bound[k]) continue;
      Lifetime& l = out[g.uses[k].resource];
      if (l.first == kNone) l.first = pos;
      l.last = pos;
    }
  }
  const uint32_t frame_end = uint32_t(schedule.order.size());
  const auto& outputs = g.graph->outputs;
  for (size_t o = 0; o < outputs.size(); ++o) {
    Lifetime& l = out[outputs[o].resource];
    if (schedule.output_live[o] && l.first != kNone) l.last = frame_end;
  }
  return out;
}

}  // namespace volgraph::compiler
