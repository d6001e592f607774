// The fog passes' shared frame block (shaders/include/fog_frame.glsl): froxel_voxelize
// packs it into its `frame` buffer; froxel_scatter, scatter_integrate and froxel_apply
// read it, so the grid, camera, lights and media they see are the same by construction.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/pass_decl.h"
#include "passes/shading/froxel.h"
#include "passes/shading/light_list.h"
#include "passes/shading/media_field.h"

namespace volgraph::fog {

struct GpuViewRays {
  float position[4], forward[4], right[4], up[4];
};
struct GpuFroxelGrid {
  uint32_t size[4];
  float range[4];
};
struct GpuFogFrame {
  GpuViewRays view;
  GpuFroxelGrid grid;
  float jitter[4];
  float ambient[4];
  shading::GpuLightList light_list;
  shading::GpuMediaField media;
};

// Bytes of the `frame` buffer slot (the block rounded up to 256).
constexpr uint64_t kFogFrameBytes = (sizeof(GpuFogFrame) + 255) / 256 * 256;

struct FogFrameInputs {
  Extent grid;                  // froxels
  shading::FroxelRange range;
  Vec3 ambient_radiance{0, 0, 0};
  bool jitter = true;
};

// The camera's rays for a frame of `output` pixels (view_rays.glsl), its near and far
// planes in position.w and forward.w.
GpuViewRays pack_view_rays(const Camera& camera, Extent output);

GpuFogFrame make_fog_frame(const PassContext& c, const FogFrameInputs& inputs);

// The scene's media must fit the frame block (at most kMaxMediumVolumes local volumes):
// the problems of a pass that packs them (`what`: how the pass uses them, "voxelized").
std::vector<ParamProblem> media_fit_problems(const Scene& scene, const std::string& what);

// Sample offset of frame `frame` inside a froxel, each axis within ±0.5: Halton (2, 3, 5)
// points, centred; frame 0 samples the centre so a single frame is deterministic.
std::array<double, 3> froxel_jitter(uint64_t frame);

}  // namespace volgraph::fog
