#include "graph/graph.h"

#include <algorithm>
#include <cmath>

namespace volgraph {

GraphBuilder::GraphBuilder(Extent output_size, SceneFeatures scene) {
  graph_.output_size = output_size;
  graph_.scene = scene;
}

void GraphBuilder::reserve(uint32_t passes, uint32_t resources) {
  graph_.passes.reserve(passes);
  graph_.resources.reserve(resources);
}

uint32_t GraphBuilder::add_pass(std::string name, const PassDecl& decl, uint16_t variant) {
  GraphPass& p = graph_.passes.emplace_back();
  p.name = std::move(name);
  p.decl = &decl;
  p.variant = variant;
  p.kind = decl.kind;
  p.needs = decl.needs;
  p.needs_any = decl.needs_any;
  p.uses.reserve(decl.slots.size());
  return static_cast<uint32_t>(graph_.passes.size() - 1);
}

void GraphBuilder::check_slot(uint32_t pass, uint16_t slot, SlotDirection direction, const GraphResource* resource) {
  const GraphPass& p = graph_.passes.at(pass);
  if (slot >= p.decl->slots.size()) throw GraphError(pass, slot, "no such slot");
  const SlotDecl& s = p.decl->slots[slot];
  if (s.direction != direction) throw GraphError(pass, slot, "slot '" + s.name + "' has another direction");
  for (const ResourceUse& u : p.uses) {
    if (u.slot == slot) throw GraphError(pass, slot, "slot '" + s.name + "' is bound twice");
  }
  if (!resource) return;
  if (resource->desc.kind != s.kind) {
    throw GraphError(pass, slot,
                     "slot '" + s.name + "' takes a " + std::string(kind_name(s.kind)) + ", but '" +
                         resource->desc.name + "' is a " + std::string(kind_name(resource->desc.kind)));
  }
  if (s.format != Format::undefined && resource->desc.format != s.format) {
    throw GraphError(pass, slot,
                     "slot '" + s.name + "' takes format " + std::string(format_info(s.format).name) + ", but '" +
                         resource->desc.name + "' is " + std::string(format_info(resource->desc.format).name));
  }
}

ResourceVersion GraphBuilder::create(uint32_t pass, uint16_t slot, ResourceDesc desc) {
  check_slot(pass, slot, SlotDirection::output, nullptr);
  GraphPass& p = graph_.passes[pass];
  const SlotDecl& s = p.decl->slots[slot];
  if (desc.name.empty()) desc.name = p.name + "." + s.name;
  if (!usage_fits_kind(s.usage, desc.kind)) {
    throw GraphError(pass, slot, "slot '" + s.name + "' cannot be used as " + std::string(usage_name(s.usage)) +
                                     " on a " + std::string(kind_name(desc.kind)));
  }
  desc.persistent = desc.persistent || s.persistent;
  GraphResource& r = graph_.resources.emplace_back();
  r.desc = std::move(desc);
  r.creator = pass;
  r.version_writers.push_back(pass);
  const uint32_t id = static_cast<uint32_t>(graph_.resources.size() - 1);
  p.uses.push_back({id, 0, slot, s.usage, SlotDirection::output, false});
  return {id, 0};
}

// A pass that reads a version through one slot and modifies it through another would
// have to run before itself: say so rather than report a cycle of one pass.
void GraphBuilder::check_not_read_and_modified(uint32_t pass, uint16_t slot, ResourceVersion what, SlotDirection direction) {
  const GraphPass& p = graph_.passes[pass];
  for (const ResourceUse& u : p.uses) {
    if (u.resource != what.resource || u.version != what.version || u.direction == direction) continue;
    if (u.direction == SlotDirection::output) continue;
    throw GraphError(pass, slot,
                     "slots '" + p.decl->slots[u.slot].name + "' and '" + p.decl->slots[slot].name + "' both take '" +
                         graph_.resources[what.resource].desc.name +
                         "', and one modifies it; read it through the modifying slot instead");
  }
}

void GraphBuilder::read(uint32_t pass, uint16_t slot, ResourceVersion what) {
  if (what.resource >= graph_.resources.size()) throw GraphError(pass, slot, "no such resource");
  const GraphResource& r = graph_.resources[what.resource];
  check_slot(pass, slot, SlotDirection::input, &r);
  if (what.version >= r.version_writers.size()) throw GraphError(pass, slot, "no such version");
  check_not_read_and_modified(pass, slot, what, SlotDirection::input);
  GraphPass& p = graph_.passes[pass];
  const SlotDecl& s = p.decl->slots[slot];
  p.uses.push_back({what.resource, what.version, slot, s.usage, SlotDirection::input, s.optional});
}

ResourceVersion GraphBuilder::modify(uint32_t pass, uint16_t slot, ResourceVersion what) {
  if (what.resource >= graph_.resources.size()) throw GraphError(pass, slot, "no such resource");
  GraphResource& r = graph_.resources[what.resource];
  check_slot(pass, slot, SlotDirection::inout, &r);
  if (what.version + 1 != r.version_writers.size()) {
    const std::string& other = graph_.passes[r.version_writers[what.version + 1]].name;
    throw GraphError(pass, slot,
                     "'" + r.desc.name + "' is already modified by pass '" + other +
                         "'; chain the modifications (wire this slot to '" + other + "')");
  }
  check_not_read_and_modified(pass, slot, what, SlotDirection::inout);
  if (r.previous != kNone) {
    throw GraphError(pass, slot,
                     "'" + r.desc.name + "' is kept as next frame's history by its pass; read it instead of modifying it");
  }
  GraphPass& p = graph_.passes[pass];
  const SlotDecl& s = p.decl->slots[slot];
  p.uses.push_back({what.resource, what.version, slot, s.usage, SlotDirection::inout, false});
  r.version_writers.push_back(pass);
  return {what.resource, what.version + 1};
}

void GraphBuilder::mark_output(ResourceVersion what) {
  if (what.resource >= graph_.resources.size()) throw GraphError(kNone, -1, "no such resource");
  const GraphResource& r = graph_.resources[what.resource];
  if (what.version + 1 != r.version_writers.size()) {
    throw GraphError(kNone, -1,
                     "graph output '" + r.desc.name + "' is modified later by pass '" +
                         graph_.passes[r.version_writers[what.version + 1]].name + "'; output that pass's slot");
  }
  if (std::find(graph_.outputs.begin(), graph_.outputs.end(), what) == graph_.outputs.end()) {
    graph_.outputs.push_back(what);
  }
}

ResourceVersion GraphBuilder::read_history(uint32_t pass, uint16_t slot, ResourceVersion current) {
  check_slot(pass, slot, SlotDirection::history, nullptr);
  const GraphPass& p = graph_.passes[pass];
  const SlotDecl& s = p.decl->slots[slot];
  const int output = p.decl->slot_index(s.history_of);
  if (current.resource >= graph_.resources.size() || output < 0 || graph_.resources[current.resource].creator != pass ||
      std::none_of(p.uses.begin(), p.uses.end(), [&](const ResourceUse& u) {
        return u.resource == current.resource && u.slot == uint16_t(output) && u.direction == SlotDirection::output;
      })) {
    throw GraphError(pass, slot, "history slot '" + s.name + "' follows output '" + s.history_of + "' of its own pass");
  }
  GraphResource& followed = graph_.resources[current.resource];
  if (followed.version_writers.size() > 1) {
    throw GraphError(pass, slot, "'" + followed.desc.name + "' is modified by pass '" +
                                     graph_.passes[followed.version_writers[1]].name + "'; a history must be the pass's own output");
  }
  if (!usage_fits_kind(s.usage, followed.desc.kind)) {
    throw GraphError(pass, slot, "history slot '" + s.name + "' cannot read a " + std::string(kind_name(followed.desc.kind)) +
                                     " as " + std::string(usage_name(s.usage)));
  }
  followed.desc.persistent = true;
  GraphResource previous;
  previous.desc = followed.desc;
  previous.desc.name = p.name + "." + s.name;
  previous.version_writers.push_back(kNone);
  previous.previous_of = current.resource;
  graph_.resources.push_back(std::move(previous));
  const uint32_t id = static_cast<uint32_t>(graph_.resources.size() - 1);
  graph_.resources[current.resource].previous = id;
  graph_.passes[pass].uses.push_back({id, 0, slot, s.usage, SlotDirection::history, false});
  return {id, 0};
}

Graph GraphBuilder::finish() { return std::move(graph_); }

namespace {

Extent extent_of(const SizeSpec& size, ResourceKind kind, Extent output_size, int64_t size_param, int64_t divisor, int64_t depth,
                 int64_t height) {
  Extent e{};
  switch (size.mode) {
    case SizeSpec::Mode::absolute:
      e = size.absolute;
      break;
    case SizeSpec::Mode::relative: {
      auto scaled = [](uint32_t n, float s) {
        return std::max<uint32_t>(1, static_cast<uint32_t>(std::lround(double(n) * s)));
      };
      const uint32_t slices = !size.param ? size.absolute.depth : uint32_t(std::max<int64_t>(1, size_param));
      const float by = !size.divisor_param ? 1.0f : 1.0f / float(std::max<int64_t>(1, divisor));
      e = {scaled(output_size.width, size.scale_x * by), scaled(output_size.height, size.scale_y * by), std::max<uint32_t>(1, slices)};
      break;
    }
    case SizeSpec::Mode::square_param: {
      const uint32_t side = static_cast<uint32_t>(std::max<int64_t>(1, size_param));
      const uint32_t fixed_high = size.fixed_height ? size.fixed_height : side;  // row_of: 1
      const uint32_t high = !size.height_param ? fixed_high : static_cast<uint32_t>(std::max<int64_t>(1, height));
      const int64_t layers = !size.depth_param ? int64_t{size.absolute.depth} : depth;
      e = {side, high, uint32_t(std::max<int64_t>(1, layers))};
      break;
    }
  }
  if (kind == ResourceKind::texture2d || kind == ResourceKind::texture_cube) e.depth = 1;  // a cube's faces are layers, not depth
  return e;
}

}  // namespace

// The levels a mip chain of `asked` levels gets at `extent`: at least 1, at most the full chain.
uint32_t mip_levels_at(Extent extent, int64_t asked) {
  return uint32_t(std::clamp<int64_t>(asked, 1, full_mip_chain(extent)));
}

ResourceDesc resolve_slot(const PassDecl& decl, const SlotDecl& slot, Extent output_size, int64_t size_param, int64_t divisor,
                          int64_t depth, int64_t height, int64_t mips) {
  ResourceDesc d;
  d.kind = slot.kind;
  d.format = slot.format;
  d.persistent = slot.persistent || decl.cached;  // a cached pass keeps its outputs across frames
  d.extent = extent_of(slot.size, slot.kind, output_size, size_param, divisor, depth, height);
  if (slot.size.mode == SizeSpec::Mode::absolute) d.buffer_bytes = slot.size.buffer_bytes;
  if (slot.kind != ResourceKind::buffer) d.mip_levels = mip_levels_at(d.extent, mips);
  return d;
}

void resize(Graph& graph, Extent output_size) {
  graph.output_size = output_size;
  for (GraphResource& r : graph.resources) {
    const SizeRule& rule = r.size_rule;
    if (rule.like != kNone) {
      r.desc.extent = graph.resources[rule.like].desc.extent;
      r.desc.mip_levels = graph.resources[rule.like].desc.mip_levels;
    } else if (r.previous_of != kNone) {
      r.desc.extent = graph.resources[r.previous_of].desc.extent;
    } else if (rule.set) {
      r.desc.extent = extent_of(rule.size, r.desc.kind, output_size, rule.side, rule.divisor, rule.depth, rule.height);
      if (r.desc.kind != ResourceKind::buffer) r.desc.mip_levels = mip_levels_at(r.desc.extent, rule.mips);
    }
  }
  // A history is made after the output it follows, but an output shaped like a history
  // (none today) would come earlier: a second sweep settles any such order.
  for (GraphResource& r : graph.resources) {
    if (r.previous_of != kNone) r.desc.extent = graph.resources[r.previous_of].desc.extent, r.desc.mip_levels = graph.resources[r.previous_of].desc.mip_levels;
  }
}

}  // namespace volgraph
