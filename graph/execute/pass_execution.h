// What a pass does on the GPU. Each pass type that can run makes one PassExecution per
// pass of a graph (PassDecl::make_execution); the executor calls record() every frame
// with the pass's resources, already in the state the plan promised.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "graph/graph.h"
#include "graph/rhi/rhi.h"

namespace volgraph {

struct Scene;

class PassContext {
 public:
  PassContext(rhi::Device& device, rhi::CommandEncoder& encoder, const Graph& graph, uint32_t pass,
              const rhi::GraphResourceSet& resources, const Scene* scene)
      : device(device), encoder(encoder), graph(graph), pass(pass), scene(scene), resources_(resources) {}

  rhi::Device& device;
  rhi::CommandEncoder& encoder;
  const Graph& graph;
  const uint32_t pass;
  const GraphPass& graph_pass() const { return graph.passes[pass]; }
  // The pass's parameter values (as its decl lists them), variant and slots' resources.
  const ParamValue& param(std::string_view name) const;
  std::string_view variant() const;
  bool bound(std::string_view slot) const;  // optional inputs may be unbound (their producer culled)
  uint32_t resource(std::string_view slot) const;
  const ResourceDesc& desc(std::string_view slot) const { return graph.resources[resource(slot)].desc; }
  rhi::TextureId texture(std::string_view slot) const { return resources_.texture(resource(slot)); }
  rhi::TextureViewId view(std::string_view slot) const { return resources_.view(resource(slot)); }
  rhi::BufferId buffer(std::string_view slot) const { return resources_.buffer(resource(slot)); }
  const Scene* scene;
  uint64_t frame = 0;  // frames run before this one (temporal passes jitter and blend by it)
  // Whether history slots hold the last frame's content (false on the first frame:
  // they hold nothing, and a pass must not read them).
  bool history_valid = false;
  // Which way round the history pairs' two objects are this frame (0 or 1; they swap
  // every frame). A pass that binds either resource of a pair — a history slot, an
  // output with one, or such an output downstream — sees other objects behind its slots
  // on odd frames: it keeps a bind group per parity. 0 for every other pass.
  uint32_t parity() const;

 private:
  const rhi::GraphResourceSet& resources_;
};

class PassExecution {
 public:
  virtual ~PassExecution() = default;
  virtual void record(PassContext& context) = 0;
};

}  // namespace volgraph
