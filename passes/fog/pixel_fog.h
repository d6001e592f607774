// What the per-pixel fog techniques (depth_fog, height_fog, analytic_fog) share: their
// slots — the scene's depth in; in-scattered radiance and transmittance out, rgba16f
// storage images at the frame's size (overridable: lower resolutions are upsampled by
// fog_apply) — and one compute dispatch over those images with the fog frame block
// (fog_frame.h, packed here: no froxel_voxelize is needed), the depth and the
// technique's own parameter block. Shaders include shaders/include/pixel_fog.glsl.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/pass_decl.h"
#include "graph/scene/scene.h"
#include "passes/shading/programs.h"

namespace volgraph::fog {

std::vector<SlotDecl> pixel_fog_slots();

class PixelFogDispatch {
 public:
  // `params`: the bytes of the shader's Params block (binding 5; empty: it has none); `ambient`: the
  // radiance the media scatter uniformly (the frame block's ambient).
  void prepare(PassContext& c, const std::string& shader, std::span<const std::byte> params, const Vec3& ambient = {0, 0, 0});
  bool prepared() const { return bool(program_.pipeline); }
  void record(PassContext& c) const;

 private:
  shading::ComputeProgram program_;
  rhi::BufferId frame_;
  rhi::BindGroupId group_;
};

}  // namespace volgraph::fog
