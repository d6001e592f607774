// The fog passes' shared frame block (shaders/include/fog_frame.glsl): froxel_voxelize
// packs it into its `frame` buffer; froxel_scatter, scatter_integrate and froxel_apply
// read it, so the grid, camera, lights and media they see are the same by construction.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/pass_decl.h"
#include "physics/froxel.h"
#include "passes/plumbing/light_list.h"
#include "passes/plumbing/scene_lighting.h"
#include "physics/media_field.h"
#include "shaders/include/fog_frame.h"
#include "shaders/include/froxel_grid.h"
#include "shaders/include/view_rays.h"

namespace volgraph::fog {

// The frame block the fog passes share: gpu::FogFrame, written once for GLSL and C++
// (shaders/include/fog_frame.h), the one member of their Frame block.

// Bytes of the `frame` buffer slot (the block rounded up to 256).
constexpr uint64_t kFogFrameBytes = (sizeof(gpu::FogFrame) + 255) / 256 * 256;

struct FogFrameInputs {
  Extent grid;                  // froxels
  physics::FroxelRange range;
  Vec3 ambient_radiance{0, 0, 0};
  bool jitter = true;
};

// The camera's rays for a frame of `output` pixels (view_rays.glsl), its near and far
// planes in position.w and forward.w.
gpu::ViewRays pack_view_rays(const Camera& camera, Extent output);

// The frame block of frame `frame` (its jitter) for the scene and frame size `s` sees: its
// lights and the ambient radiance (the inputs' plus the sky's) as `lighting` gives them.
gpu::FogFrame make_fog_frame(const PassSetup& s, uint64_t frame, const FogFrameInputs& inputs, plumbing::SceneLighting& lighting);

// The scene's media must fit the frame block (at most kMaxMediumVolumes local volumes):
// the problems of a pass that packs them (`what`: how the pass uses them, "voxelized").
std::vector<ParamProblem> media_fit_problems(const Scene& scene, const std::string& what);

// Sample offset of frame `frame` inside a froxel, each axis within ±0.5: Halton (2, 3, 5)
// points, centred; frame 0 samples the centre so a single frame is deterministic.
std::array<double, 3> froxel_jitter(uint64_t frame);

}  // namespace volgraph::fog
