// The scene's objects on the device, shared by every pass that rasterises them (scene,
// shadow_map): one vertex and index buffer per object and its set-1 bind group — a
// uniform block with its transforms and material factors (shaders/include/
// object_uniforms.glsl) and, for passes that shade, the material's textures
// (shaders/include/material_textures.glsl).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "graph/rhi/bind_by_name.h"
#include "graph/rhi/rhi.h"
#include "graph/scene/scene.h"
#include "physics/camera.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/textures.h"
#include "shaders/include/object_uniforms.h"

namespace volgraph::plumbing {

// The most draws (a primitive object is one, a glTF object one per primitive) a scene
// may have: each draw takes its own vertex, index and uniform buffers and bind group,
// which lavapipe backs with memory maps of their own; near 8,150 objects (a frame with a
// shadow map) the process runs out of them (Linux's vm.max_map_count, 65530) and the
// driver crashes, on Vulkan and under Dawn alike. Half that leaves room for the rest of
// the frame; the scene pass refuses more at validate time.
constexpr size_t kMaxSceneDraws = 4096;

// The Object block (set 1): written once for GLSL and C++ (shaders/include/object_uniforms.h).
using GpuObjectBlock = gpu::ObjectUniforms;

// Which of the scene's surfaces a pass draws: the opaque ones (alpha mode opaque or mask,
// no transmission), the translucent ones (Translucency::translucent), or the opaque ones
// whose object casts shadows (Object::cast_shadows), without or with an alpha mask (the
// shadow map's depth-only and alpha-tested draws), or the translucent ones whose object casts
// shadows (translucent_shadow_map's coloured transmittance).
enum class Surfaces : uint8_t { opaque, translucent, solid_shadow_casters, masked_shadow_casters, translucent_shadow_casters };

struct GpuObject {
  rhi::BufferId vertices, indices, uniforms;
  rhi::BindGroupId group;
  uint32_t index_count = 0;
  bool translucent = false;
  bool casts_shadows = true;
  bool masked = false;  // alpha mode mask
  VolumeKind volume = VolumeKind::thin_walled;
  Vec3 center{0, 0, 0};  // of its world-space bounds (translucent draws sort by it)
  // Translucent ones: convex or flat (every vertex behind every face's plane), so a pixel
  // meets it at most once per face set (the translucency pass blends a layer in one draw).
  bool convex = false;
  bool is(Surfaces which) const {
    switch (which) {
      case Surfaces::opaque: return !translucent;
      case Surfaces::translucent: return translucent;
      case Surfaces::solid_shadow_casters: return !translucent && casts_shadows && !masked;
      case Surfaces::masked_shadow_casters: return !translucent && casts_shadows && masked;
      case Surfaces::translucent_shadow_casters: return translucent && casts_shadows;
    }
    return false;
  }
};

// A material's texture images (null: a factor alone).
struct MaterialTextures {
  std::function<Rgba8Image()> base_color, emissive;
  std::string base_color_key, emissive_key;
  // glTF's transmission (red) and thickness (green) textures, stored linear.
  std::function<Rgba8Image()> transmission, thickness;
  std::string transmission_key, thickness_key;
  SamplerWrap wrap;
};

class SceneGeometry {
 public:
  // Set 1 as the program's shaders declare it (scene.frag's `object` and material): the object
  // block alone (depth passes) or with the material's textures. The object block is
  // checked against GpuObjectBlock (plumbing::check_uniform_mirror). glTF objects are
  // loaded here (throws std::runtime_error for a broken file).
  SceneGeometry(rhi::Device& device, const Scene& scene, const RenderProgram& program);
  const std::vector<GpuObject>& objects() const { return objects_; }
  // Vertex buffer layouts: position, normal and texture coordinate at locations 0, 1, 2;
  // or the position alone (depth passes).
  static rhi::VertexBufferLayout vertex_layout();
  static rhi::VertexBufferLayout position_layout();
  // The position and texture coordinate (locations 0 and 2: alpha-tested depth passes).
  static rhi::VertexBufferLayout position_uv_layout();
  // World-space bounds of every object (for fitting light projections).
  Vec3 bounds_min() const { return min_; }
  Vec3 bounds_max() const { return max_; }
  // Binds set `set` and draws every object of the kind (the pipeline is set by the caller).
  void draw(rhi::CommandEncoder& encoder, uint32_t set, Surfaces which = Surfaces::opaque) const;
  // Binds set `set` and draws one object.
  static void draw(rhi::CommandEncoder& encoder, uint32_t set, const GpuObject& object);
  // Whether any object is of the kind.
  bool any(Surfaces which) const;

 private:
  struct ObjectData {
    const std::vector<float>& vertices;
    const std::vector<uint32_t>& indices;
    const physics::Mat4& model;
    Vec3 albedo, emissive;
    const Translucency& translucency;
    const MaterialTextures& textures;
    bool casts_shadows;
  };
  void add(rhi::Device& device, const ObjectData& object);
  std::vector<rhi::BoundResource> texture_entries(const MaterialTextures& textures);
  std::vector<rhi::BoundResource> translucent_texture_entries(const MaterialTextures& textures);

  bool textured_ = false;
  bool translucent_textured_ = false;  // set 1 declares translucent_material_textures.glsl's too
  std::unique_ptr<TextureCache> textures_;
  rhi::BindGroupLayoutId layout_;
  std::vector<GpuObject> objects_;
  Vec3 min_{1e30, 1e30, 1e30}, max_{-1e30, -1e30, -1e30};
};

}  // namespace volgraph::plumbing
