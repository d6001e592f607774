// What a pass does on the GPU. Each pass type that can run makes one PassExecution per
// pass of a graph (PassDecl::make_execution). Its lifecycle: setup() once, after the
// graph is compiled and its resources exist (pipelines, layouts, constant blocks), then
// record() every frame with the pass's resources already in the state the plan promised.
// Bind groups are not kept: record() asks for them by content (PassContext::bind_group),
// and the device's cache returns the same group for the same layout and entries, so a
// history pair whose objects swap every frame simply gets two.
#pragma once

#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include "graph/graph.h"
#include "graph/plan.h"
#include "graph/rhi/bind_by_name.h"
#include "graph/rhi/graph_resource_set.h"
#include "graph/rhi/rhi.h"

namespace volgraph {

struct Scene;

// What a pass sees of itself and its resources, at setup and at every frame.
class PassSetup {
 public:
  PassSetup(rhi::Device& device, const Graph& graph, uint32_t pass, const rhi::GraphResourceSet& resources, const Scene* scene)
      : device(device), graph(graph), pass(pass), scene(scene), resources_(resources) {}

  rhi::Device& device;
  const Graph& graph;
  const uint32_t pass;
  const Scene* scene;
  const GraphPass& graph_pass() const { return graph.passes[pass]; }
  const std::string& name() const { return graph_pass().name; }
  // The frame's size the graph is compiled for (the camera's aspect); a pass's own
  // extents come from its slots (extent()).
  Extent frame_size() const { return graph.output_size; }

  // The pass's parameter values, variant and slots, through its table's handles.
  template <typename T>
  const T& param(ParamHandle<T> handle) const {
    return std::get<T>(param_value(handle.index));
  }
  template <typename Enum>
  Enum param(const ChoiceHandle<Enum>& handle) const {
    return handle.value_of(param(handle.text));
  }
  const VariantDecl& variant() const { return graph_pass().decl->variants[graph_pass().variant]; }
  bool variant_is(VariantHandle v) const { return graph_pass().variant == v.index; }
  // Which step is recording (a pass made of steps, PassDecl::steps).
  bool step_is(StepHandle s) const { return graph_pass().step == s.index; }
  // The pass's own name (a step's graph pass is "<name>/<step>").
  std::string pass_name() const { return name().substr(0, name().find('/')); }
  bool bound(SlotHandle slot) const;  // optional inputs may be unbound (their producer culled)
  uint32_t resource(SlotHandle slot) const;
  const ResourceDesc& desc(SlotHandle slot) const { return graph.resources[resource(slot)].desc; }
  Extent extent(SlotHandle slot) const { return desc(slot).extent; }
  rhi::TextureId texture(SlotHandle slot) const { return resources_.texture(resource(slot)); }
  rhi::TextureViewId view(SlotHandle slot) const { return resources_.view(resource(slot)); }
  // One mip level of the slot's texture (storage images take one level: generate_mips).
  rhi::TextureViewId view(SlotHandle slot, uint32_t level) const { return resources_.level_view(resource(slot), level); }
  // One face of the slot's cube at level 0 (a render target: scene_probe draws each face).
  rhi::TextureViewId face_view(SlotHandle slot, uint32_t face) const { return resources_.face_view(resource(slot), face); }
  rhi::BufferId buffer(SlotHandle slot) const { return resources_.buffer(resource(slot)); }
  // The integer parameter `param` of the pass that makes the resource wired to `slot`: a
  // reader takes its input's shape from its producer (one source for it, never a copy of
  // its own that may disagree). Throws when that pass has no such parameter.
  int64_t producer_param(SlotHandle slot, std::string_view param) const;

  // One of the device's shared samplers.
  rhi::SamplerId sampler(rhi::StockSampler which) const { return device.stock_sampler(which); }

  // States what the pass chose at setup and why (Plan::setup_notes, `plan --setup`).
  void note(std::string text) const {
    if (notes_) notes_->push_back({pass, std::move(text)});
  }
  void collect_notes(std::vector<SetupNote>* notes) { notes_ = notes; }

 private:
  std::vector<SetupNote>* notes_ = nullptr;
  const ParamValue& param_value(uint16_t index) const;
  const ResourceUse* use_of(SlotHandle slot) const;
  const rhi::GraphResourceSet& resources_;
};

// A frame of the pass: where it records, and what frame it is.
class PassContext : public PassSetup {
 public:
  PassContext(rhi::Device& device, rhi::CommandEncoder& encoder, const Graph& graph, uint32_t pass,
              const rhi::GraphResourceSet& resources, const Scene* scene)
      : PassSetup(device, graph, pass, resources, scene), encoder(encoder) {}

  rhi::CommandEncoder& encoder;
  uint64_t frame = 0;  // frames run before this one (temporal passes jitter and blend by it)
  // Whether history slots hold the last frame's content (false on the first frame:
  // they hold nothing, and a pass must not read them).
  bool history_valid = false;

  // The bind group of `layout` holding `entries`, from the device's cache.
  rhi::BindGroupId bind_group(rhi::BindGroupLayoutId layout, std::vector<rhi::BindGroupEntry> entries) const;

  // The bind group of the program's set that `resources` name (rhi::bind, by the shader's
  // variables): checked first, so an entry of another set, one the layout lacks or a binding
  // left out throws std::logic_error naming the pass, the shader and the variable.
  template <typename Program>
    requires requires(const Program& p) { p.layout_descs; p.shader; }
  rhi::BindGroupId bind_group(const Program& program, const std::vector<rhi::BoundResource>& resources) const {
    const uint32_t set = rhi::check_bound_set(resources, program.layout_descs, name(), program.shader);
    return bind_group(program.layouts[set], rhi::entries_of(resources));
  }
};

class PassExecution {
 public:
  virtual ~PassExecution() = default;
  // Once, before the first frame: pipelines, layouts, blocks that do not change.
  virtual void setup(PassSetup& setup) { (void)setup; }
  virtual void record(PassContext& context) = 0;
};

// The PassDecl of a pass type whose table is `Table` (a PassTable) and whose execution
// is `Execution`, constructed from the table: `Execution(const Table&)`.
template <typename Table, typename Execution>
PassDecl pass_type() {
  auto table = std::make_shared<const Table>();
  PassDecl decl = table->decl;
  if (decl.variants.empty()) decl.variants.push_back({"default", "the pass's only way"});
  decl.make_execution = [table]() -> std::unique_ptr<PassExecution> { return std::make_unique<Execution>(*table); };
  finish_steps(decl);  // after make_execution: the steps share it
  return decl;
}

}  // namespace volgraph
