#include "graph/execute/pass_execution.h"

#include <stdexcept>

namespace volgraph {

const ParamValue& PassContext::param(std::string_view name) const {
  const GraphPass& p = graph_pass();
  const int i = p.decl->param_index(name);
  if (i < 0) throw std::logic_error(p.decl->name + " has no parameter " + std::string(name));
  if (size_t(i) < p.params.size()) return p.params[size_t(i)];
  return p.decl->params[size_t(i)].default_value;
}

std::string_view PassContext::variant() const { return graph_pass().decl->variants[graph_pass().variant].name; }

// Wired in the graph and given memory by the plan (an optional input whose producer was
// culled is wired but unbound).
bool PassContext::bound(std::string_view slot) const {
  const GraphPass& p = graph_pass();
  const int s = p.decl->slot_index(slot);
  for (const ResourceUse& u : p.uses) {
    if (int(u.slot) != s) continue;
    const bool buffer = graph.resources[u.resource].desc.kind == ResourceKind::buffer;
    return buffer ? bool(resources_.buffer(u.resource)) : bool(resources_.texture(u.resource));
  }
  return false;
}

uint32_t PassContext::resource(std::string_view slot) const {
  const GraphPass& p = graph_pass();
  const int s = p.decl->slot_index(slot);
  for (const ResourceUse& u : p.uses) {
    if (int(u.slot) == s) return u.resource;
  }
  throw std::logic_error(p.name + ": slot " + std::string(slot) + " is not bound");
}

uint32_t PassContext::parity() const {
  for (const ResourceUse& u : graph_pass().uses) {
    const GraphResource& r = graph.resources[u.resource];
    if (r.previous != kNone || r.previous_of != kNone) return uint32_t(frame & 1);
  }
  return 0;
}

}  // namespace volgraph
