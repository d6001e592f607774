#include "graph/probe.h"

#include <algorithm>

namespace volgraph {
namespace {

// The last use of `slot` by `pass` or any of its steps (graph passes "pass/step", in step
// order): what the pass leaves in it. Null when the pass exists and does not bind the slot.
const ResourceUse* last_use_of(const Graph& graph, const std::string& pass, const std::string& slot, const Where& where) {
  const ResourceUse* last = nullptr;
  bool named = false;
  for (const GraphPass& g : graph.passes) {
    if (g.name != pass && g.name.rfind(pass + "/", 0) != 0) continue;
    named = true;
    const int s = g.decl->slot_index(slot);
    for (const ResourceUse& u : g.uses) {
      if (int(u.slot) == s) last = &u;
    }
  }
  if (!named) throw ConfigError({{where, "no pass named \"" + pass + "\""}});
  return last;
}

// The name a graph pass has for the user: its steps ("pass/step") are the pass's.
std::string user_pass_name(const GraphPass& g) { return g.name.substr(0, g.name.find('/')); }

}  // namespace

ResourceVersion find_probe(const Graph& graph, const std::string& pass_dot_slot, const Where& where) {
  auto fail = [&](const std::string& message) { throw ConfigError({{where, message}}); };
  const std::string request = pass_dot_slot.substr(0, pass_dot_slot.find('='));
  const size_t dot = request.find('.');
  if (dot == std::string::npos) fail("expected PASS.SLOT");
  const std::string pass = request.substr(0, dot), slot = request.substr(dot + 1);
  const ResourceUse* use = last_use_of(graph, pass, slot, where);
  if (!use) fail("pass \"" + pass + "\" has no bound slot \"" + slot + "\"");
  const uint32_t version = use->direction == SlotDirection::inout ? use->version + 1 : use->version;
  const GraphResource& r = graph.resources[use->resource];
  if (version + 1 != r.version_writers.size()) {
    fail(pass + "." + slot + " is modified later by pass \"" + user_pass_name(graph.passes[r.version_writers[version + 1]]) +
         "\"; use that pass's slot");
  }
  return {use->resource, version};
}

uint32_t probe_slot(Graph& graph, const std::string& pass_dot_slot, const Where& where) {
  const ResourceVersion probed = find_probe(graph, pass_dot_slot, where);
  if (std::find(graph.outputs.begin(), graph.outputs.end(), probed) == graph.outputs.end()) graph.outputs.push_back(probed);
  return probed.resource;
}

std::vector<std::string> probe_names(const Graph& graph) {
  std::vector<std::string> names;
  for (const GraphPass& g : graph.passes) {
    for (const ResourceUse& u : g.uses) {
      if (u.direction == SlotDirection::input) continue;
      const ResourceKind kind = graph.resources[u.resource].desc.kind;
      if (kind == ResourceKind::buffer) continue;
      const std::string name = user_pass_name(g) + "." + g.decl->slots[u.slot].name;
      if (std::find(names.begin(), names.end(), name) != names.end()) continue;
      try {
        find_probe(graph, name, {});
        names.push_back(name);
      } catch (const ConfigError&) {
        // modified later by another pass: that pass's slot is listed instead
      }
    }
  }
  return names;
}

}  // namespace volgraph
