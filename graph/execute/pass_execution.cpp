#include "graph/execute/pass_execution.h"

#include <stdexcept>
#include <string>

namespace volgraph {

const ParamValue& PassSetup::param_value(uint16_t index) const {
  const GraphPass& p = graph_pass();
  if (index < p.params.size()) return p.params[index];
  return p.decl->params.at(index).default_value;
}

// Wired in the graph and given memory by the plan (an optional input whose producer was
// culled is wired but unbound).
// The use of `slot` by this pass — by any of its steps when it has steps, this one's first.
const ResourceUse* PassSetup::use_of(SlotHandle slot) const {
  const GraphPass& p = graph_pass();
  for (const ResourceUse& u : p.uses) {
    if (u.slot == slot.index) return &u;
  }
  if (p.group == kNone) return nullptr;
  for (const GraphPass& step : graph.passes) {
    if (step.group != p.group) continue;
    for (const ResourceUse& u : step.uses) {
      if (u.slot == slot.index) return &u;
    }
  }
  return nullptr;
}

int64_t PassSetup::producer_param(SlotHandle slot, std::string_view param) const {
  const uint32_t creator = graph.resources[resource(slot)].creator;
  const GraphPass* producer = creator == kNone ? nullptr : &graph.passes[creator];
  const int index = producer ? producer->decl->param_index(param) : -1;
  if (index < 0) {
    throw std::logic_error(graph_pass().name + ": slot " + graph_pass().decl->slots.at(slot.index).name +
                           " is not made by a pass with an integer parameter " + std::string(param));
  }
  const ParamValue& value = size_t(index) < producer->params.size() ? producer->params[size_t(index)]
                                                                     : producer->decl->params.at(size_t(index)).default_value;
  return std::get<int64_t>(value);
}

bool PassSetup::bound(SlotHandle slot) const {
  const ResourceUse* u = use_of(slot);
  if (!u) return false;
  const bool buffer = graph.resources[u->resource].desc.kind == ResourceKind::buffer;
  return buffer ? bool(resources_.buffer(u->resource)) : bool(resources_.texture(u->resource));
}

uint32_t PassSetup::resource(SlotHandle slot) const {
  if (const ResourceUse* u = use_of(slot)) return u->resource;
  throw std::logic_error(graph_pass().name + ": slot " + graph_pass().decl->slots.at(slot.index).name + " is not bound");
}

rhi::BindGroupId PassContext::bind_group(rhi::BindGroupLayoutId layout, std::vector<rhi::BindGroupEntry> entries) const {
  return device.cached_bind_group({name(), layout, std::move(entries)});
}

}  // namespace volgraph
