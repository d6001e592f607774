// The std140 mirrors of the passes' own uniform blocks (a pass's Params or frame block,
// filled by that pass alone), here rather than in the pass files so that
// tests/unit/uniform_mirrors_test.cpp can check each against the shaders that declare it.
// Each lists its members' offsets in offsets() (passes/plumbing/programs.h), which the
// pass's check at setup uses. The blocks several passes share are next to their packing:
// fog::GpuFogFrame (fog/fog_frame.h), plumbing::GpuLightList (plumbing/light_list.h),
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

namespace volgraph {

// The scene pass's Frame (shaders/include/scene_uniforms.glsl).
struct GpuSceneFrame {
  float view_projection[16];
  float ambient_irradiance[4];
  plumbing::GpuLightList light_list;
  physics::GpuMediaField media;  // the global and height fog (no volumes): they dim the light toward each surface
  static constexpr std::array<uint64_t, 4> offsets() {
    return {offsetof(GpuSceneFrame, view_projection), offsetof(GpuSceneFrame, ambient_irradiance),
            offsetof(GpuSceneFrame, light_list), offsetof(GpuSceneFrame, media)};
  }
};

// The scene pass's `frame` output: GpuSceneFrame, padded to 256 bytes.
constexpr uint64_t kSceneFrameBytes = (sizeof(GpuSceneFrame) + 255) / 256 * 256;

// The sky pass's frame (shaders/include/atmosphere_sky_frame.glsl SkyPassFrame, the only
// member of every variant's Frame block).
struct GpuSkyFrame {
  gpu::ViewRays view;
  float planet_up[4];     // xyz: the camera's local zenith; w: its radius (m, at most the top's: the sky-view LUT's)
  float toward_sun[4];    // xyz: unit, toward the sun; w: the sun's zenith cosine at the camera
  float sun[4];           // rgb: E at the top of the atmosphere; w: 1 when there is a sun
  float sun_disk[4];      // x: the sun's angular radius (rad), y: 1 to draw its disk, z: 1 to limb-darken it, w: 1 to draw the ground
  float camera[4];        // x: the camera's radius as it is (m), y: 1 for the multiple-scattering term
  float sampling[4];      // min and max samples a ray, the length (m) from which rays take the max, where in its step each sample sits
  static constexpr std::array<uint64_t, 7> offsets() {
    return {offsetof(GpuSkyFrame, view), offsetof(GpuSkyFrame, planet_up), offsetof(GpuSkyFrame, toward_sun), offsetof(GpuSkyFrame, sun),
            offsetof(GpuSkyFrame, sun_disk), offsetof(GpuSkyFrame, camera), offsetof(GpuSkyFrame, sampling)};
  }
};

// atmosphere_aerial_perspective.comp's Frame.
struct GpuAerialPerspectiveFrame {
  gpu::ViewRays view;
  float planet_up[4];   // xyz: the camera's local zenith; w: its radius (m, at most the top's)
  float toward_sun[4];  // xyz: unit, toward the sun; w: the sun's zenith cosine at the camera
  float volume[4];      // x: metres a slice (along each ray), y: 1 when there is a sun
  float sampling[4];    // min and max samples, the length (m) from which rays take the max, where in its step each sample sits
  static constexpr std::array<uint64_t, 5> offsets() {
    return {offsetof(GpuAerialPerspectiveFrame, view), offsetof(GpuAerialPerspectiveFrame, planet_up),
            offsetof(GpuAerialPerspectiveFrame, toward_sun), offsetof(GpuAerialPerspectiveFrame, volume),
            offsetof(GpuAerialPerspectiveFrame, sampling)};
  }
};

// The aerial-perspective volumes' frame (shaders/include/atmosphere_aerial_lookup.glsl
// AerialLookup): atmosphere_aerial_perspective writes it to its `lookup` output for the
// passes that read the volumes.
struct GpuAerialLookup {
  gpu::ViewRays view;
  float volume[4];  // x: the distance the volume reaches (m), y: its slices
  float sun[4];     // rgb: the sun's E at the top of the atmosphere (0 without a sun)
  static constexpr std::array<uint64_t, 3> offsets() {
    return {offsetof(GpuAerialLookup, view), offsetof(GpuAerialLookup, volume), offsetof(GpuAerialLookup, sun)};
  }
};
// Bytes of atmosphere_aerial_perspective's `lookup` buffer (the block rounded up to 256).
constexpr uint64_t kAerialLookupBytes = (sizeof(GpuAerialLookup) + 255) / 256 * 256;

// light_volume.glsl's LightVolumeParams, the one member of the light_volume shaders'
// Params block (plumbing::check_wrapped_uniform_mirror).
struct GpuLightVolumeParams {
  float camera_clip[16];
  int32_t sizes[4];
  static constexpr std::array<uint64_t, 2> offsets() {
    return {offsetof(GpuLightVolumeParams, camera_clip), offsetof(GpuLightVolumeParams, sizes)};
  }
};

}  // namespace volgraph
