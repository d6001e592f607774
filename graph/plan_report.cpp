#include "graph/plan_report.h"

#include <cstdio>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "graph/pooling.h"

namespace volgraph {
namespace {

using Json = nlohmann::ordered_json;

std::string extent_text(const ResourceDesc& d) {
  if (d.kind == ResourceKind::buffer) return std::to_string(d.buffer_bytes) + " B";
  std::string s = std::to_string(d.extent.width) + "x" + std::to_string(d.extent.height);
  if (d.kind == ResourceKind::texture3d) s += "x" + std::to_string(d.extent.depth);
  if (d.kind == ResourceKind::texture_cube) s += " cube";
  return s;
}

std::string variant_of(const GraphPass& p) { return p.decl->variants[p.variant].name; }

std::string resource_name(const Graph& g, uint32_t r) { return r == kNone ? "(all memory)" : g.resources[r].desc.name; }

Json state_json(const AccessState& s) {
  return {{"stages", stage_names(s.stages)}, {"access", access_names(s.access)}, {"layout", layout_name(s.layout)}};
}

std::string barrier_text(const Graph& g, const Barrier& b) {
  std::string s = resource_name(g, b.resource) + ": ";
  if (b.from.layout != b.to.layout) s += std::string(layout_name(b.from.layout)) + " → " + std::string(layout_name(b.to.layout)) + ", ";
  s += stage_names(b.from.stages) + "/" + access_names(b.from.access) + " → " + stage_names(b.to.stages) + "/" +
       access_names(b.to.access);
  if (b.aliasing) s += "  (aliasing hand-over)";
  return s;
}

std::string dot_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

// ", history pair with X (its last frame)" / ", history pair with X (the output it follows)".
std::string history_text(const Graph& g, uint32_t r) {
  const GraphResource& res = g.resources[r];
  if (res.previous != kNone) return ", history pair with " + g.resources[res.previous].desc.name + " (its last frame)";
  if (res.previous_of != kNone) return ", history pair with " + g.resources[res.previous_of].desc.name + " (the output it follows)";
  return "";
}

// Bytes of the used history pairs (both objects): part of the persistent bytes.
uint64_t history_bytes(const Graph& g, const Plan& plan) {
  uint64_t bytes = 0;
  for (uint32_t r = 0; r < g.resources.size(); ++r) {
    const GraphResource& res = g.resources[r];
    const bool paired = res.previous != kNone || res.previous_of != kNone;
    if (paired && plan.lifetimes[r].first != kNone) bytes += plan.placements[r].requirements.size;
  }
  return bytes;
}

Json barrier_json(const Graph& g, const Barrier& br) {
  return {{"resource", br.resource == kNone ? Json(nullptr) : Json(resource_name(g, br.resource))},
          {"from", state_json(br.from)},
          {"to", state_json(br.to)},
          {"aliasing", br.aliasing}};
}

// The pass a setup note is of: a pass made of steps is set up once, by its first step.
std::string noted_pass(const Graph& g, const SetupNote& n) {
  const std::string& name = g.passes[n.pass].name;
  return name.substr(0, name.find('/'));
}

}  // namespace

std::string bytes_text(uint64_t bytes) {
  char buf[64];
  if (bytes >= (1ull << 20)) std::snprintf(buf, sizeof buf, "%.2f MiB", double(bytes) / double(1ull << 20));
  else if (bytes >= 1024) std::snprintf(buf, sizeof buf, "%.1f KiB", double(bytes) / 1024.0);
  else std::snprintf(buf, sizeof buf, "%llu B", static_cast<unsigned long long>(bytes));
  return buf;
}

std::string plan_text(const Graph& g, const Plan& plan, const PlanReportContext& context) {
  std::ostringstream o;
  o << "plan";
  if (!context.config_file.empty()) o << " for " << context.config_file;
  o << " (" << g.output_size.width << "x" << g.output_size.height << "; scene has " << features_text(g.scene) << ")\n";
  o << "options: cull " << (plan.options.cull ? "on" : "off") << ", alias " << (plan.options.alias ? "on" : "off")
    << ", serialize " << (plan.options.serialize ? "on" : "off") << "\n\norder:\n";
  for (size_t i = 0; i < plan.order.size(); ++i) {
    const PlannedPass& pp = plan.order[i];
    const GraphPass& p = g.passes[pp.pass];
    o << "  " << i << ". " << p.name << "  (" << p.decl->name << "/" << variant_of(p) << ", " << pass_kind_name(p.kind)
      << (p.decl->cached ? ", cached: skipped while its key holds" : "") << ")\n";
    for (uint32_t b = pp.barrier_begin; b < pp.barrier_begin + pp.barrier_count; ++b) {
      o << "       barrier " << barrier_text(g, plan.barriers[b]) << "\n";
    }
  }
  o << "\nculled:" << (plan.culled.empty() ? " none\n" : "\n");
  for (const CulledPass& c : plan.culled) {
    o << "  " << g.passes[c.pass].name << "  " << cull_reason_name(c.reason) << ": " << cull_detail(g, c) << "\n";
  }
  if (!plan.setup_notes.empty()) o << "\nset up on the device:\n";
  for (const SetupNote& n : plan.setup_notes) o << "  " << noted_pass(g, n) << "  " << n.text << "\n";
  o << "\nresources (lifetime in plan positions):\n";
  for (uint32_t r = 0; r < g.resources.size(); ++r) {
    const Lifetime& l = plan.lifetimes[r];
    const ResourceDesc& d = g.resources[r].desc;
    o << "  " << d.name << "  " << kind_name(d.kind);
    if (d.kind != ResourceKind::buffer) o << " " << format_info(d.format).name;
    o << " " << extent_text(d);
    if (l.first == kNone) {
      o << "  unused\n";
      continue;
    }
    const Placement& pl = plan.placements[r];
    o << "  [" << l.first << ", " << l.last << "]  " << bytes_text(pl.requirements.size);
    if (pl.heap == kNone) o << "  persistent, own memory" << history_text(g, r) << "\n";
    else o << "  heap " << pl.heap << " @ " << pl.offset << "\n";
  }
  o << "\nbefore the first frame:" << (plan.initial_barriers.empty() ? " nothing\n" : "\n");
  for (const Barrier& b : plan.initial_barriers) o << "  barrier " << barrier_text(g, b) << "\n";
  o << "\nhand-overs (aliasing):" << (plan.handovers.empty() ? " none\n" : "\n");
  for (const Handover& h : plan.handovers) {
    o << "  " << resource_name(g, h.resource) << " takes over bytes of " << resource_name(g, h.previous) << "\n";
  }
  const MemoryStats& m = plan.memory;
  o << "\nmemory: " << m.transient_count << " transient resources; unaliased " << bytes_text(m.unaliased_bytes)
    << ", aliased " << bytes_text(m.aliased_bytes) << ", lower bound " << bytes_text(m.lower_bound_bytes)
    << "; persistent " << bytes_text(m.persistent_bytes) << " (history " << bytes_text(history_bytes(g, plan))
    << "); placement " << placement_method_name(m.method) << "\n";
  const ResourcePool pool = pool_resources(g, plan);
  o << "pooled (WebGPU, no placed memory): " << pool.transient_objects << " objects for " << m.transient_count
    << " transient resources, " << bytes_text(pool.transient_bytes) << "\n";
  o << "barriers: " << plan.barriers.size() << "\n";
  return o.str();
}

std::string plan_json(const Graph& g, const Plan& plan, const PlanReportContext& context) {
  Json j;
  j["config"] = context.config_file;
  j["output_size"] = {g.output_size.width, g.output_size.height};
  j["scene_features"] = features_text(g.scene);
  j["options"] = {{"cull", plan.options.cull}, {"alias", plan.options.alias}, {"serialize", plan.options.serialize}};
  Json order = Json::array();
  for (const PlannedPass& pp : plan.order) {
    const GraphPass& p = g.passes[pp.pass];
    Json barriers = Json::array();
    for (uint32_t b = pp.barrier_begin; b < pp.barrier_begin + pp.barrier_count; ++b) {
      barriers.push_back(barrier_json(g, plan.barriers[b]));
    }
    order.push_back({{"pass", p.name}, {"type", p.decl->name}, {"variant", variant_of(p)},
                     {"kind", pass_kind_name(p.kind)}, {"cached", p.decl->cached}, {"barriers", barriers}});
  }
  j["order"] = order;
  Json initial = Json::array();
  for (const Barrier& b : plan.initial_barriers) initial.push_back(barrier_json(g, b));
  j["initial_barriers"] = initial;
  Json culled = Json::array();
  for (const CulledPass& c : plan.culled) {
    culled.push_back({{"pass", g.passes[c.pass].name}, {"reason", cull_reason_name(c.reason)}, {"detail", cull_detail(g, c)}});
  }
  j["culled"] = culled;
  Json notes = Json::array();
  for (const SetupNote& n : plan.setup_notes) notes.push_back({{"pass", noted_pass(g, n)}, {"note", n.text}});
  if (!plan.setup_notes.empty()) j["setup_notes"] = notes;
  Json resources = Json::array();
  for (uint32_t r = 0; r < g.resources.size(); ++r) {
    const ResourceDesc& d = g.resources[r].desc;
    const Lifetime& l = plan.lifetimes[r];
    const Placement& pl = plan.placements[r];
    Json res = {{"name", d.name}, {"kind", kind_name(d.kind)}, {"persistent", d.persistent}};
    const GraphResource& gr = g.resources[r];
    if (gr.previous != kNone) res["history"] = {{"role", "current"}, {"pair", g.resources[gr.previous].desc.name}};
    if (gr.previous_of != kNone) res["history"] = {{"role", "previous"}, {"pair", g.resources[gr.previous_of].desc.name}};
    if (d.kind == ResourceKind::buffer) res["bytes"] = d.buffer_bytes;
    else res["format"] = format_info(d.format).name, res["extent"] = {d.extent.width, d.extent.height, d.extent.depth};
    if (l.first == kNone) {
      res["used"] = false;
    } else {
      res["used"] = true;
      res["lifetime"] = {l.first, l.last};
      res["size"] = pl.requirements.size;
      res["alignment"] = pl.requirements.alignment;
      res["heap"] = pl.heap == kNone ? Json(nullptr) : Json(pl.heap);
      res["offset"] = pl.offset;
    }
    resources.push_back(res);
  }
  j["resources"] = resources;
  Json heaps = Json::array();
  for (const Heap& h : plan.heaps) heaps.push_back({{"class", h.heap_class}, {"size", h.size}, {"alignment", h.alignment}});
  j["heaps"] = heaps;
  Json handovers = Json::array();
  for (const Handover& h : plan.handovers) {
    handovers.push_back({{"resource", resource_name(g, h.resource)}, {"previous", resource_name(g, h.previous)}});
  }
  j["handovers"] = handovers;
  const MemoryStats& m = plan.memory;
  j["memory"] = {{"transient_resources", m.transient_count}, {"unaliased_bytes", m.unaliased_bytes},
                 {"aliased_bytes", m.aliased_bytes}, {"lower_bound_bytes", m.lower_bound_bytes},
                 {"persistent_bytes", m.persistent_bytes}, {"history_bytes", history_bytes(g, plan)},
                 {"placement", placement_method_name(m.method)}};
  const ResourcePool pool = pool_resources(g, plan);
  j["memory"]["pooled_objects"] = pool.transient_objects;
  j["memory"]["pooled_bytes"] = pool.transient_bytes;
  return j.dump(2) + "\n";
}

std::string plan_dot(const Graph& g, const Plan& plan, const PlanReportContext& context) {
  std::ostringstream o;
  o << "digraph plan {\n  rankdir=LR;\n  node [shape=box, style=\"rounded,filled\", fillcolor=\"#e8f0fe\", fontname=\"Helvetica\"];\n";
  o << "  label=\"" << dot_escape(context.config_file) << "\";\n";
  std::map<uint32_t, const CulledPass*> culled;
  for (const CulledPass& c : plan.culled) culled[c.pass] = &c;
  for (uint32_t p = 0; p < g.passes.size(); ++p) {
    const GraphPass& pass = g.passes[p];
    o << "  p" << p << " [label=\"";
    if (plan.position[p] != kNone) o << plan.position[p] << ". ";
    o << dot_escape(pass.name) << "\\n" << dot_escape(pass.decl->name + "/" + variant_of(pass));
    if (auto it = culled.find(p); it != culled.end()) {
      o << "\\nculled: " << cull_reason_name(it->second->reason) << "\", style=\"rounded,dashed\", fillcolor=\"#eeeeee\", fontcolor=\"#777777\"";
    } else {
      o << "\"";
    }
    o << "];\n";
  }
  for (uint32_t p = 0; p < g.passes.size(); ++p) {
    for (const ResourceUse& u : g.passes[p].uses) {
      if (u.direction == SlotDirection::output) continue;
      if (u.direction == SlotDirection::history) {  // from the pass itself, a frame earlier
        o << "  p" << p << " -> p" << p << " [label=\"" << dot_escape(g.resources[u.resource].desc.name)
          << " (last frame)\", style=dotted];\n";
        continue;
      }
      const uint32_t from = g.resources[u.resource].version_writers[u.version];
      const bool dead = plan.position[p] == kNone || plan.position[from] == kNone;
      o << "  p" << from << " -> p" << p << " [label=\"" << dot_escape(g.resources[u.resource].desc.name) << "\""
        << (dead ? ", style=dashed, color=\"#999999\"" : "") << "];\n";
    }
  }
  for (size_t i = 0; i < g.outputs.size(); ++i) {
    const GraphResource& r = g.resources[g.outputs[i].resource];
    const uint32_t from = r.version_writers[g.outputs[i].version];
    o << "  out" << i << " [shape=oval, fillcolor=\"#d9f2d9\", label=\"" << dot_escape(r.desc.name) << "\"];\n";
    if (from != kNone) o << "  p" << from << " -> out" << i << ";\n";  // kNone: a history, made by the last frame
  }
  o << "}\n";
  return o.str();
}

}  // namespace volgraph
