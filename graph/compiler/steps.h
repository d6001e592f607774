// The compiler's steps, in the order compile() runs them. Internal to graph/compiler.
#pragma once

#include <vector>

#include "graph/plan.h"

namespace volgraph::compiler {

// The graph as flat arrays (compressed rows), built once per compile so that every
// step walks memory in order instead of chasing per-pass and per-resource vectors.
struct FlatGraph {
  const Graph* graph = nullptr;
  std::vector<uint32_t> use_begin;       // per pass + 1: its uses are uses[use_begin[p] .. use_begin[p + 1])
  std::vector<ResourceUse> uses;
  std::vector<uint32_t> version_begin;   // per resource + 1: its versions' writers in version_writer
  std::vector<uint32_t> version_writer;  // the pass that made each version
  std::vector<PassKind> pass_kind;       // per pass
  std::vector<SceneFeatures> pass_needs;      // per pass
  std::vector<SceneFeatures> pass_needs_any;  // per pass: at least one of these (0: no condition)
  std::vector<ResourceKind> resource_kind;  // per resource

  uint32_t pass_count() const { return uint32_t(use_begin.size() - 1); }
  uint32_t resource_count() const { return uint32_t(version_begin.size() - 1); }
  uint32_t version_index(uint32_t r, uint32_t v) const { return version_begin[r] + v; }
  uint32_t writer(uint32_t r, uint32_t v) const { return version_writer[version_begin[r] + v]; }
  uint32_t version_count(uint32_t r) const { return version_begin[r + 1] - version_begin[r]; }
};

FlatGraph flatten(const Graph& graph);

struct Schedule {
  std::vector<uint32_t> order;     // live passes, execution order
  std::vector<uint32_t> position;  // per pass: index in order or kNone
  std::vector<CulledPass> culled;
  // Per use (flat index): whether it is bound. An optional input whose version does
  // not exist (its producer was culled) is left unbound.
  std::vector<uint8_t> bound;
  std::vector<uint8_t> output_live;  // per graph output: its producer runs
};

// Topological order (ties broken by declaration order) and culling. Throws on a cycle.
Schedule order_and_cull(const FlatGraph& graph, bool cull);

std::vector<Lifetime> lifetimes(const FlatGraph& graph, const Schedule& schedule);

struct MemoryLayout {
  std::vector<Placement> placements;
  std::vector<Heap> heaps;
  std::vector<Handover> handovers;
  MemoryStats stats;
};

MemoryLayout place_memory(const Graph& graph, const std::vector<Lifetime>& lifetimes, bool alias,
                          const RequirementsFn& requirements);

struct BarrierPlan {
  std::vector<Barrier> barriers;              // sorted by position
  std::vector<uint32_t> begin, count;         // per position
  std::vector<Barrier> initial;               // Plan::initial_barriers
  std::vector<AccessState> final_states;      // Plan::final_states
};

BarrierPlan plan_barriers(const FlatGraph& graph, const Schedule& schedule, const std::vector<Handover>& handovers,
                          bool serialize);

}  // namespace volgraph::compiler
