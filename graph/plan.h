// What the compiler decides: pass order, culling, lifetimes, memory and barriers.
// A backend executes a Plan as is: it allocates what `memory` says and records
// exactly the barriers listed before each pass.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "graph/access.h"
#include "graph/graph.h"

namespace volgraph {

struct CompileOptions {
  bool cull = true;        // --no-cull: keep every pass
  bool alias = true;       // --no-alias: every transient gets its own bytes
  bool serialize = false;  // --serialize: a full barrier between every two passes
};

struct MemoryRequirements {
  uint64_t size = 0;
  uint64_t alignment = 1;
  uint32_t heap_class = 0;  // resources share bytes only within a class
};

// What a backend says resource `resource` (index into Graph::resources) takes, e.g. from
// the VkImage it made for it; without one, the compiler estimates from the format.
using RequirementsFn = std::function<MemoryRequirements(uint32_t resource, const ResourceDesc&)>;
MemoryRequirements estimate_requirements(const ResourceDesc& desc);

// A pass culled for its scene needs forwards its inout slots: downstream readers of the
// version it would have made read the version it was given (same physical resource).
enum class CullReason : uint8_t {
  scene_lacks,  // a scene feature the pass needs is missing
  input_culled, // a required input comes from a culled pass
  unused,       // none of its outputs reaches a graph output
};
std::string_view cull_reason_name(CullReason reason);

struct CulledPass {
  uint32_t pass;
  CullReason reason;
  SceneFeatures missing = 0;  // scene_lacks: the features the scene lacks
  uint16_t slot = 0;          // input_culled: the required input whose producer was culled
  SceneFeatures missing_any = 0;  // scene_lacks: the pass's needs_any when the scene has none of them
};

// "scene has no medium", "scene has no medium or clouds", "input 'volume' (fog.volume) comes from a culled pass", …
std::string cull_detail(const Graph& graph, const CulledPass& culled);

struct Lifetime {
  uint32_t first = kNone;  // position in `order` of the first use
  uint32_t last = kNone;   // position of the last use (order.size() for graph outputs)
};

struct Placement {
  uint32_t heap = kNone;  // kNone: its own allocation (persistent or not aliasable)
  uint64_t offset = 0;
  MemoryRequirements requirements{};
};

struct Heap {
  uint32_t heap_class = 0;
  uint64_t size = 0;
  uint64_t alignment = 1;
};

// A resource takes over bytes another used before: the new occupant starts undefined
// and its first use waits for the previous occupant's last access.
struct Handover {
  uint32_t resource;
  uint32_t previous;
};

struct Barrier {
  uint32_t resource = kNone;  // kNone: a global memory barrier (--serialize)
  AccessState from{};         // src scope; layout is the old layout
  AccessState to{};           // dst scope; layout is the new layout
  bool aliasing = false;      // first use after a hand-over
};

struct PlannedPass {
  uint32_t pass;             // index into Graph::passes
  uint32_t barrier_begin;    // barriers recorded before this pass, batched
  uint32_t barrier_count;
};

// How transient resources got their offsets (the one used for the largest heap class
// when classes differ): greedy by size while few resources are alive together, a
// linear scan with best fit past that, side by side under --no-alias.
enum class PlacementMethod : uint8_t { unaliased, greedy_by_size, linear_scan };
std::string_view placement_method_name(PlacementMethod method);

struct MemoryStats {
  PlacementMethod method = PlacementMethod::unaliased;
  uint64_t unaliased_bytes = 0;   // transient resources side by side (what --no-alias allocates)
  uint64_t aliased_bytes = 0;     // sum of heap sizes
  uint64_t lower_bound_bytes = 0; // most bytes live at once (per heap class, summed)
  uint64_t persistent_bytes = 0;  // never aliased
  uint64_t transient_count = 0;
};

// What a pass chose when it was set up on the device (a capability it used or went
// without, and why): filled by the executor, printed by `plan --setup`.
struct SetupNote {
  uint32_t pass;
  std::string text;
};

struct Plan {
  CompileOptions options{};
  std::vector<PlannedPass> order;
  std::vector<CulledPass> culled;
  std::vector<uint32_t> position;       // per graph pass: index in order, kNone if culled
  std::vector<Lifetime> lifetimes;      // per graph resource; first == kNone when unused
  std::vector<Placement> placements;    // per graph resource
  std::vector<Heap> heaps;
  std::vector<Handover> handovers;
  std::vector<Barrier> barriers;
  // Recorded once, before the first frame: each persistent texture from undefined
  // contents to the state `barriers` assume every frame starts in (the steady state of
  // repeated frames, history pairs swapping their objects between frames).
  std::vector<Barrier> initial_barriers;
  // Per graph resource: where a frame leaves it, for whatever follows the frame
  // (read-backs): its layout, and the stages of its last write and of every read since.
  std::vector<AccessState> final_states;
  MemoryStats memory{};
  std::vector<SetupNote> setup_notes;  // empty until an executor has set the passes up
};

// Orders, culls, places and synchronises. Throws GraphError on a cycle.
Plan compile(const Graph& graph, const CompileOptions& options = {}, const RequirementsFn& requirements = {});

}  // namespace volgraph
