// The sizes of the buffers passes share that hold a struct written once for GLSL and C++
// (GPU_STRUCT under shaders/include/, gpu_struct.h), rounded up as a uniform binding wants:
// the scene pass's frame and the aerial lookup. No hand-written mirror of a uniform block is
// left; every shared struct's layout is asserted at compile time against each shader.
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
#include "shaders/include/scene_frame.h"
#include "shaders/include/sky_pass_frame.h"

namespace volgraph {

// The scene pass's `frame` output: gpu::SceneFrame (shaders/include/scene_frame.h), padded to 256 bytes.
constexpr uint64_t kSceneFrameBytes = (sizeof(gpu::SceneFrame) + 255) / 256 * 256;

// Bytes of atmosphere_aerial_perspective's `lookup` buffer (the block rounded up to 256).
constexpr uint64_t kAerialLookupBytes = (sizeof(gpu::AerialLookup) + 255) / 256 * 256;

}  // namespace volgraph
