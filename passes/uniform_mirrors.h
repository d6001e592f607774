// The std140 mirrors of the passes' own uniform blocks (a pass's Params or frame block,
// filled by that pass alone), here rather than in the pass files so that
// tests/unit/uniform_mirrors_test.cpp can check each against the shaders that declare it.
// Each lists its members' offsets in offsets() (passes/plumbing/programs.h), which the
// pass's check at setup uses. The blocks several passes share are next to their packing:
// gpu::FogFrame (fog/fog_frame.h), gpu::LightList (plumbing/light_list.h),
// plumbing::ShadowViewBlock (plumbing/shadow_view.h) and plumbing::GpuObjectBlock
// (plumbing/scene_geometry.h). The structs written once for GLSL and C++ are in
// shaders/include/ (GPU_STRUCT, gpu_struct.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "passes/fog/fog_frame.h"
#include "passes/plumbing/light_list.h"
#include "physics/media_field.h"
#include "shaders/include/aerial_lookup.h"
#include "shaders/include/aerial_perspective_frame.h"
#include "shaders/include/light_volume_params.h"
#include "shaders/include/sky_pass_frame.h"

namespace volgraph {

// The scene pass's Frame (shaders/include/scene_uniforms.glsl).
struct GpuSceneFrame {
  float view_projection[16];
  float ambient_irradiance[4];
  gpu::LightList light_list;
  gpu::MediaField media;  // the global and height fog (no volumes): they dim the light toward each surface
  static constexpr std::array<uint64_t, 4> offsets() {
    return {offsetof(GpuSceneFrame, view_projection), offsetof(GpuSceneFrame, ambient_irradiance),
            offsetof(GpuSceneFrame, light_list), offsetof(GpuSceneFrame, media)};
  }
};

// The scene pass's `frame` output: GpuSceneFrame, padded to 256 bytes.
constexpr uint64_t kSceneFrameBytes = (sizeof(GpuSceneFrame) + 255) / 256 * 256;

// Bytes of atmosphere_aerial_perspective's `lookup` buffer (the block rounded up to 256).
constexpr uint64_t kAerialLookupBytes = (sizeof(gpu::AerialLookup) + 255) / 256 * 256;

}  // namespace volgraph
