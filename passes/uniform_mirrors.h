// The std140 mirrors left of the passes' own uniform blocks: the scene pass's frame (and
// the aerial-lookup and light-volume sizes derived from shared structs). Each lists its
// members' offsets in offsets() (passes/plumbing/programs.h), which the pass's check at setup
// uses, and tests/unit/uniform_mirrors_test.cpp checks it against every shader that declares
// it. Every other block holds a struct written once for GLSL and C++ under shaders/include/
// (GPU_STRUCT, gpu_struct.h), its layout asserted at compile time.
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
