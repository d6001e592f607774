// The graph's resources on WebGPU, which has no placed memory: transient resources are
// pooled (graph/pooling.h) — one texture or buffer per pooled object, handed to each of
// its occupants in turn, whose lifetimes never overlap. An object's usage is the union
// of its occupants' uses in the graph (and copy source for graph outputs, which are
// read back), nothing more: a pass using a resource in a way its slots did not declare
// is a Dawn validation error. Memory requirements are the compiler's estimate (WebGPU
// does not expose the driver's), so the pooled figure of `plan` is what is created.
#pragma once

#include <vector>

#include <webgpu/webgpu_cpp.h>

#include "graph/pooling.h"
#include "graph/rhi/graph_resource_set.h"
#include "graph/rhi/rhi.h"

namespace volgraph::webgpu {

class WebGpuDevice;

class WebGpuGraphResources final : public rhi::GraphResourceSet {
 public:
  WebGpuGraphResources(WebGpuDevice& device, const Graph& graph);

  RequirementsFn requirements() const override { return {}; }
  void bind(const Plan& plan) override;
  rhi::TextureId texture(uint32_t resource) const override { return textures_.at(resource); }
  rhi::TextureViewId view(uint32_t resource) const override { return views_.at(resource); }
  rhi::TextureViewId level_view(uint32_t resource, uint32_t level) const override {
    const std::vector<rhi::TextureViewId>& levels = level_views_.at(resource);
    return levels.empty() && level == 0 ? views_.at(resource) : levels.at(level);
  }
  rhi::TextureViewId face_view(uint32_t resource, uint32_t face) const override {
    const std::vector<rhi::TextureViewId>& faces = face_views_.at(resource);
    return face < faces.size() ? faces[face] : rhi::TextureViewId{};
  }
  rhi::BufferId buffer(uint32_t resource) const override { return buffers_.at(resource); }
  void swap(uint32_t a, uint32_t b) override;

  // What bind() created: one object per pooled object.
  struct Created {
    uint32_t transient_objects = 0;
    uint64_t transient_bytes = 0;  // each object's estimated requirement (estimate_requirements)
    uint32_t persistent_objects = 0;
  };
  const Created& created() const { return created_; }

 private:
  void create_object(const PooledObject& object, uint32_t index);

  WebGpuDevice& device_;
  const Graph& graph_;
  std::vector<wgpu::TextureUsage> texture_usage_;  // per graph resource
  std::vector<wgpu::BufferUsage> buffer_usage_;
  std::vector<rhi::TextureId> textures_;  // per graph resource: its pooled object's
  std::vector<rhi::TextureViewId> views_;
  std::vector<std::vector<rhi::TextureViewId>> level_views_;  // a mip chain's levels, one view each (storage takes one)
  std::vector<std::vector<rhi::TextureViewId>> face_views_;   // a cube's faces at level 0 (attachments)
  std::vector<rhi::BufferId> buffers_;
  Created created_;
};

}  // namespace volgraph::webgpu
