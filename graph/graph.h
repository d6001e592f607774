// The wired graph the compiler takes: passes, the resources they create, and every
// use of a resource by a pass, with versions (a pass that modifies a resource makes
// a new version of it). Built by the config loader, or directly with GraphBuilder.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "graph/pass_decl.h"
#include "graph/resource.h"

namespace volgraph {

constexpr uint32_t kNone = 0xffffffffu;

struct ResourceVersion {
  uint32_t resource = kNone;
  uint32_t version = 0;
  friend bool operator==(const ResourceVersion&, const ResourceVersion&) = default;
};

struct ResourceUse {
  uint32_t resource = kNone;
  uint32_t version = 0;  // the version read; a writer makes version + 1 (a creator makes 0)
  uint16_t slot = 0;     // index into the pass decl's slots
  Usage usage = Usage::sampled;
  SlotDirection direction = SlotDirection::input;
  bool optional = false;
};

struct GraphPass {
  std::string name;
  const PassDecl* decl = nullptr;
  uint16_t variant = 0;
  PassKind kind = PassKind::compute;
  SceneFeatures needs = 0;
  SceneFeatures needs_any = 0;  // at least one of these (PassDecl::needs_any)
  std::vector<ResourceUse> uses;
  std::vector<ParamValue> params;  // as the decl's params; empty: the defaults
  // A step of a pass made of steps (PassDecl::steps): the graph pass of its first step
  // (the pass's own index, where the config's passes are), and which step this is.
  uint32_t group = kNone;
  uint16_t step = 0;
};

// A history pair: an output a history slot follows (`previous` set) and the resource
// that slot reads (`previous_of` set), last frame's content of the output — made by no
// pass of this frame (creator and version 0's writer kNone). Both are persistent; the
// executor swaps their physical objects every frame.
// How a resource's extent follows the frame's size, so that a graph compiled for
// another size (resize()) needs no reloading: the slot's size as the config resolved it
// and the parameter values it names, or the resource it is shaped like.
struct SizeRule {
  bool set = false;  // false: the extent is fixed (buffers, graphs built by hand)
  SizeSpec size{};
  int64_t side = 0, divisor = 1, depth = 1, height = 0;  // the values of the size's parameters (resolve_slot)
  int64_t mips = 1;  // the mip chain's levels asked for (SizeSpec::mip_param), before the extent clamps them
  uint32_t like = kNone;  // shaped like this resource (an output_like slot's input)
};

struct GraphResource {
  ResourceDesc desc;
  SizeRule size_rule;
  uint32_t creator = kNone;              // pass that makes version 0 (kNone: made by the last frame)
  std::vector<uint32_t> version_writers;  // pass that made version v (v = 0: creator)
  uint32_t previous = kNone;             // an output with a history: the resource holding its last frame
  uint32_t previous_of = kNone;          // a history: the output whose last frame it holds
};

struct Graph {
  Extent output_size{};
  SceneFeatures scene = 0;
  std::vector<GraphPass> passes;
  std::vector<GraphResource> resources;
  std::vector<ResourceVersion> outputs;  // what the frame delivers
};

// A graph that cannot be built (wiring broken): what and where, in graph terms.
class GraphError : public std::runtime_error {
 public:
  GraphError(uint32_t pass, int slot, const std::string& message)
      : std::runtime_error(message), pass(pass), slot(slot) {}
  uint32_t pass;  // kNone when not about one pass
  int slot;       // -1 when not about one slot
};

class GraphBuilder {
 public:
  GraphBuilder(Extent output_size, SceneFeatures scene);

  // Room for this many passes and resources, when the caller knows (no regrowth).
  void reserve(uint32_t passes, uint32_t resources);

  uint32_t add_pass(std::string name, const PassDecl& decl, uint16_t variant = 0);
  // Creates the resource of an output slot; desc.name is filled in when empty.
  ResourceVersion create(uint32_t pass, uint16_t slot, ResourceDesc desc);
  void read(uint32_t pass, uint16_t slot, ResourceVersion what);
  // An inout slot: reads `what` and makes the next version of the same resource.
  ResourceVersion modify(uint32_t pass, uint16_t slot, ResourceVersion what);
  void mark_output(ResourceVersion what);
  // A history slot of `pass` following `current`, the output the pass creates through
  // the slot's history_of: makes the previous-frame resource and reads it.
  ResourceVersion read_history(uint32_t pass, uint16_t slot, ResourceVersion current);

  Graph& graph() { return graph_; }
  Graph finish();

 private:
  void check_slot(uint32_t pass, uint16_t slot, SlotDirection direction, const GraphResource* resource);
  void check_not_read_and_modified(uint32_t pass, uint16_t slot, ResourceVersion what, SlotDirection direction);
  Graph graph_;
};

// The graph for frames of `output_size`: every resource's extent resolved again by its
// size rule (those shaped like another and histories follow theirs), as compile() then
// sees it. Parameters, wiring and formats are unchanged: no config is reloaded.
void resize(Graph& graph, Extent output_size);

// The resource desc an output slot of `decl` gets in a frame of `output_size`
// (size_param: the value of a square_param size, 0 when unused).
// `size_param`: the value of the slot's size parameter (SizeSpec::param), `divisor`: of
// its divisor parameter (SizeSpec::divisor_param), `depth`: of its depth parameter
// (SizeSpec::depth_param), `height`: of its height parameter (SizeSpec::height_param), when
// it has them.
// `mips`: of its mip parameter (SizeSpec::mip_param), clamped to the extent's full chain.
ResourceDesc resolve_slot(const PassDecl& decl, const SlotDecl& slot, Extent output_size, int64_t size_param,
                          int64_t divisor = 1, int64_t depth = 1, int64_t height = 0, int64_t mips = 1);

}  // namespace volgraph
