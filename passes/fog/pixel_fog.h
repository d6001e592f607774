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

namespace volgraph::fog {

std::vector<SlotDecl> pixel_fog_slots();

// What a technique hands its shader: the bytes of its Params block (binding 5; empty: it
// has none) and the radiance the media scatter uniformly (the frame block's ambient).
struct PixelFogInputs {
  std::vector<std::byte> params;
  Vec3 ambient{0, 0, 0};
};
using PixelFogInputsOf = PixelFogInputs (*)(const PassContext& c);

// The technique's execution: `shader` dispatched over the two images, with the inputs
// `inputs_of` gives on the first frame.
MakeExecution pixel_fog_execution(std::string shader, PixelFogInputsOf inputs_of);

// The ambient parameter's value, for techniques that declare one.
Vec3 ambient_param(const PassContext& c);

}  // namespace volgraph::fog
