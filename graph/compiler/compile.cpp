#include "graph/compiler/steps.h"

namespace volgraph {

std::string_view cull_reason_name(CullReason reason) {
  switch (reason) {
    case CullReason::scene_lacks: return "scene_lacks";
    case CullReason::input_culled: return "input_culled";
    case CullReason::unused: return "unused";
  }
  return "?";
}

std::string_view placement_method_name(PlacementMethod method) {
  switch (method) {
    case PlacementMethod::unaliased: return "unaliased";
    case PlacementMethod::greedy_by_size: return "greedy_by_size";
    case PlacementMethod::linear_scan: return "linear_scan";
  }
  return "?";
}

namespace {
// "medium", "medium or clouds", "atmosphere; medium or clouds": all of needs, then needs_any.
std::string missing_text(const CulledPass& culled) {
  if (!culled.missing_any) return features_text(culled.missing);
  if (!culled.missing) return features_or_text(culled.missing_any);
  return features_text(culled.missing) + "; " + features_or_text(culled.missing_any);
}
}  // namespace

std::string cull_detail(const Graph& graph, const CulledPass& culled) {
  switch (culled.reason) {
    case CullReason::scene_lacks:
      return "scene has no " + missing_text(culled);
    case CullReason::input_culled: {
      const GraphPass& pass = graph.passes[culled.pass];
      std::string resource;
      for (const ResourceUse& u : pass.uses) {
        if (u.slot == culled.slot) resource = graph.resources[u.resource].desc.name;
      }
      return "input '" + pass.decl->slots[culled.slot].name + "' (" + resource + ") comes from a culled pass";
    }
    case CullReason::unused:
      return "no output of it reaches a graph output";
  }
  return "";
}

Plan compile(const Graph& graph, const CompileOptions& options, const RequirementsFn& requirements) {
  using namespace compiler;
  Plan plan;
  plan.options = options;
  const FlatGraph flat = flatten(graph);
  Schedule schedule = order_and_cull(flat, options.cull);
  plan.lifetimes = lifetimes(flat, schedule);
  MemoryLayout memory = place_memory(graph, plan.lifetimes, options.alias, requirements);
  BarrierPlan barriers = plan_barriers(flat, schedule, memory.handovers, options.serialize);

  plan.order.reserve(schedule.order.size());
  for (uint32_t pos = 0; pos < schedule.order.size(); ++pos) {
    plan.order.push_back({schedule.order[pos], barriers.begin[pos], barriers.count[pos]});
  }
  plan.culled = std::move(schedule.culled);
  plan.position = std::move(schedule.position);
  plan.placements = std::move(memory.placements);
  plan.heaps = std::move(memory.heaps);
  plan.handovers = std::move(memory.handovers);
  plan.memory = memory.stats;
  plan.barriers = std::move(barriers.barriers);
  plan.initial_barriers = std::move(barriers.initial);
  plan.final_states = std::move(barriers.final_states);
  return plan;
}

}  // namespace volgraph
