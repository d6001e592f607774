// The scene's objects on the device, shared by every pass that rasterises them (scene,
// shadow_map): one vertex and index buffer per object and a uniform block with its
// transforms and material (shaders/include/scene_uniforms.glsl, set 1).
#pragma once

#include <vector>

#include "graph/rhi/rhi.h"
#include "graph/scene/scene.h"
#include "passes/shading/camera.h"

namespace volgraph::shading {

struct GpuObject {
  rhi::BufferId vertices, indices, uniforms;
  rhi::BindGroupId group;
  uint32_t index_count = 0;
};

class SceneGeometry {
 public:
  // glTF objects are loaded here (throws std::runtime_error for a broken file).
  SceneGeometry(rhi::Device& device, const Scene& scene);
  const std::vector<GpuObject>& objects() const { return objects_; }
  rhi::BindGroupLayoutId layout() const { return layout_; }
  // World-space bounds of every object (for fitting light projections).
  Vec3 bounds_min() const { return min_; }
  Vec3 bounds_max() const { return max_; }
  // Binds set `set` and draws every object (the pipeline is set by the caller).
  void draw(rhi::CommandEncoder& encoder, uint32_t set) const;

 private:
  void add(rhi::Device& device, const std::vector<float>& vertices, const std::vector<uint32_t>& indices, const Mat4& model,
           const Vec3& albedo, const Vec3& emissive);

  rhi::BindGroupLayoutId layout_;
  std::vector<GpuObject> objects_;
  Vec3 min_{1e30, 1e30, 1e30}, max_{-1e30, -1e30, -1e30};
};

}  // namespace volgraph::shading
