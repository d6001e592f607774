// Temporal accumulation (froxel_temporal, pixel_temporal) in whole graphs on both backends
// (each pass's own cases: froxel_temporal_test.cpp, pixel_temporal_test.cpp; the fixture is
// temporal_fog.h):
// - the froxel chain over frames (configs/tests/oracle_fog_sphere.json) comes closer to the
//   CPU reference;
// - stress scenes over several frames, the camera moving: no NaN or Inf in the history;
// - passes after a temporal pass (scatter_integrate, fog_apply, composite) read this frame's
//   object of the history pair;
// - the fog demos run frame after frame with a moving camera.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "graph/rhi/device_error.h"
#include "tests/gpu/fog_scenes.h"
#include "tests/gpu/shipped_configs.h"
#include "tests/gpu/temporal_fog.h"
#include "tests/support/fog_accuracy.h"

namespace volgraph::testing {
namespace {

class TemporalFog : public TemporalFogFixture {};

// The whole froxel chain (configs/graphs/froxel_fog.json: froxel_temporal before
// scatter_integrate and froxel_apply) on the oracle fog sphere (configs/tests/) against
// the CPU reference (tests/support/fog_accuracy.h metric: every pixel sees fog only
// here). With jitter on and alpha 1/64, 16 blended frames average each froxel's
// footprint: far closer than one jittered frame alone (measured 8.4 % against 24.2 % at
// frame 15 with alpha 1, no accumulation). Frame 0's centre rays are closer still (6.8 %):
// froxel_voxelize averages the sphere's chord along each ray exactly, so what jitter adds
// on this hard-edged sphere is the footprint's lateral average, a column-wide blur of its
// silhouette under the bilinear lookup.
TEST_P(TemporalFog, TheFroxelChainOverFramesComesCloserToTheCpuReference) {
  Overrides o;
  o.sets = {"fog_media.jitter=true", "fog_temporal.alpha=0.015625"};
  LoadedConfig config = accuracy::load_linear(config_path("tests/oracle_fog_sphere.json"), registry_, o);
  const reference::ReferenceImage reference = accuracy::render_reference(config);
  const std::vector<bool> fog_only = accuracy::fog_only_pixels(config.config.scene, config.config.output_size.width,
                                                               config.config.output_size.height);
  Frames frames(device(), config);
  const double one = accuracy::compare_fog(frames.next()[0], reference, fog_only).difference.relative_mean_error;
  for (int f = 1; f < 15; ++f) frames.next();
  const double sixteen = accuracy::compare_fog(frames.next()[0], reference, fog_only).difference.relative_mean_error;
  o.sets.back() = "fog_temporal.alpha=1";
  LoadedConfig unblended = accuracy::load_linear(config_path("tests/oracle_fog_sphere.json"), registry_, o);
  Frames alone(device(), unblended);
  for (int f = 0; f < 15; ++f) alone.next();
  const double jittered = accuracy::compare_fog(alone.next()[0], reference, fog_only).difference.relative_mean_error;
  std::printf("froxel chain vs the CPU reference (oracle fog sphere): 1 frame %.4f, 16 jittered frames blended %.4f, frame 15 alone %.4f\n",
              one, sixteen, jittered);
  EXPECT_LT(sixteen, 0.5 * jittered);
  EXPECT_LT(sixteen, 0.1);
}

// Stress media over twelve frames with jitter, the camera moving each frame: no NaN or
// Inf in the blended volume or images, which are also the next frame's histories.
TEST_P(TemporalFog, StressScenesLeaveNoNanOrInfInTheHistoryOverManyFrames) {
  for (const char* m : kStressMedia) {
    FroxelCase froxels;
    froxels.media = m;
    froxels.lights = kStressLights;
    froxels.grid = R"({ "tile": 8, "slices": 16, "near": 0.001, "far": 100000, "distribution": "exponential", "jitter": true })";
    PixelCase pixels;
    pixels.media = m;
    pixels.lights = kStressLights;
    pixels.march = R"({ "steps": 8, "max_distance": 100000, "jitter": true })";
    for (const std::string& text : {froxel_config(froxels), pixel_config(pixels)}) {
      LoadedConfig config = load(text);
      Frames frames(device(), config);
      for (int f = 0; f < 12; ++f) {
        frames.camera().position[2] = frames.camera().target[2] = -0.1 * f;
        const std::vector<Texels> t = frames.next();
        for (size_t o = 0; o < 2; ++o) {
          for (size_t k = 0; k < t[o].rgba.size(); ++k) {
            ASSERT_TRUE(std::isfinite(t[o].rgba[k])) << "frame " << f << " output " << o << " value " << k << " of " << m;
          }
        }
      }
    }
  }
}

// With alpha 1 the blend is this frame's value exactly, so a pass reading the blended
// output must see what a twin pass reading this frame's value directly sees — on every
// frame, also the odd ones, where the history pairs' objects are the other way round
// (a pass that kept frame 0's bind group would read last frame's). scatter_integrate
// after froxel_temporal, and fog_apply after pixel_temporal, with jitter on.
TEST_P(TemporalFog, PassesAfterATemporalPassReadThisFramesObjectOfTheHistoryPair) {
  const std::string froxels = R"({ "output": { "size": [32, 24] },
  "scene": { "camera": )" + camera_at(0) + R"(, "lights": )" + kPointLight + R"(, "media": )" + kSphereMedia + R"( },
  "graph": { "passes": [
    { "name": "fog_media", "type": "froxel_voxelize", "params": { "slices": 16, "near": 0.5, "far": 12, "jitter": true } },
    { "name": "fog_light", "type": "froxel_scatter",
      "inputs": { "media_scattering": "fog_media.media_scattering", "media_emission": "fog_media.media_emission", "frame": "fog_media.frame" } },
    { "name": "fog_temporal", "type": "froxel_temporal", "params": { "alpha": 1 },
      "inputs": { "in_scatter": "fog_light.in_scatter", "frame": "fog_media.frame" } },
    { "name": "through", "type": "scatter_integrate",
      "inputs": { "in_scatter": "fog_temporal.accumulated", "media_scattering": "fog_media.media_scattering",
                  "media_absorption": "fog_media.media_absorption", "frame": "fog_media.frame" } },
    { "name": "direct", "type": "scatter_integrate",
      "inputs": { "in_scatter": "fog_light.in_scatter", "media_scattering": "fog_media.media_scattering",
                  "media_absorption": "fog_media.media_absorption", "frame": "fog_media.frame" } } ],
    "outputs": ["through.integrated_scattering", "direct.integrated_scattering"] } })";
  PixelCase pixel_case;
  const std::string pixels = R"({ "output": { "size": [32, 24] },
  "scene": { "camera": )" + camera_at(0) + R"(, "lights": )" + kPointLight + R"(,
             "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } }, "objects": )" + pixel_case.objects + R"(, "media": )" + pixel_case.media + R"( },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "lit_too", "type": "scene" },
    { "name": "fog_march", "type": "raymarch_fog", "params": { "steps": 8, "max_distance": 12 }, "inputs": { "depth": "lit.depth" } },
    { "name": "fog_temporal", "type": "pixel_temporal", "params": { "alpha": 1 },
      "inputs": { "depth": "lit.depth", "fog_scattering": "fog_march.fog_scattering", "fog_transmittance": "fog_march.fog_transmittance" } },
    { "name": "through", "type": "fog_apply",
      "inputs": { "color": "lit.color", "fog_scattering": "fog_temporal.scattering", "fog_transmittance": "fog_temporal.transmittance" } },
    { "name": "direct", "type": "fog_apply",
      "inputs": { "color": "lit_too.color", "fog_scattering": "fog_march.fog_scattering", "fog_transmittance": "fog_march.fog_transmittance" } } ],
    "outputs": ["through.color", "direct.color"] } })";
  for (const std::string& text : {froxels, pixels}) {
    LoadedConfig config = load(text);
    Frames frames(device(), config);
    for (int f = 0; f < 4; ++f) {
      const std::vector<Texels> t = frames.next();
      ASSERT_TRUE(t[0].rgba == t[1].rgba) << "frame " << f << " of " << config.graph.passes.back().decl->name;
    }
  }
}

// A pass that binds a history pair's output (composite reading pixel_temporal's
// `scattering`, whose object swaps with its history every frame) sees this frame's object
// every frame: its bind groups come from the device's cache by content, so on odd frames
// it gets the group of the other object. Composite `none` copies its input exactly, so
// each frame's output equals that frame's scattering; had it kept frame 0's group it
// would show the last frame's (the camera moves, so the two differ).
TEST_P(TemporalFog, APassReadingAHistoryPairSeesThisFramesObject) {
  const std::string text = R"({ "output": { "size": [32, 24] },
  "scene": { "camera": )" + camera_at(0) + R"(, "media": { "fog": { "sigma_s": [0.1, 0.1, 0.1], "sigma_a": [0, 0, 0] } },
             "lights": [ { "type": "point", "position": [0, 2, -3], "intensity": [20, 20, 20] } ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "fog_march", "type": "raymarch_fog", "inputs": { "depth": "lit.depth" } },
    { "name": "fog_temporal", "type": "pixel_temporal",
      "inputs": { "depth": "lit.depth", "fog_scattering": "fog_march.fog_scattering", "fog_transmittance": "fog_march.fog_transmittance" } },
    { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "fog_temporal.scattering" } } ],
    "outputs": ["out.output", "fog_temporal.scattering"] } })";
  LoadedConfig config = load(text);
  Frames frames(device(), config);
  std::vector<float> last_frame;
  for (int f = 0; f < 4; ++f) {
    frames.camera().position[0] = 0.3 * f;
    frames.camera().target[0] = 0.3 * f;
    const std::vector<Texels> out = frames.next();
    ASSERT_EQ(out[0].rgba.size(), out[1].rgba.size());
    for (size_t i = 0; i < out[0].rgba.size(); i += 4) {
      for (size_t k = 0; k < 3; ++k) ASSERT_EQ(out[0].rgba[i + k], out[1].rgba[i + k]) << "frame " << f << " texel " << i / 4;
    }
    EXPECT_NE(out[1].rgba, last_frame) << "frame " << f << " repeats the last: the test would not see a stale group";
    last_frame = out[1].rgba;
  }
}

// The shipped fog demos (their graphs now accumulate over frames) at the GPU tests' size,
// six frames with the camera moving: validation silent (TearDown), histories swapped and
// read by scatter_integrate and fog_apply through bind groups from the device's cache, and the
// output finite.
TEST_P(TemporalFog, TheFogDemosRunFrameAfterFrameWithAMovingCamera) {
  for (const char* demo : {"demo_fog.json", "demo_godrays.json", "demo_raymarch_fog.json"}) {
    Overrides o;
    o.size = kConfigTestSize;
    LoadedConfig config = load_config(config_path(demo), registry_, o);
    Frames frames(device(), config);
    for (int f = 0; f < 6; ++f) {
      frames.camera().position[0] += 0.05;
      const Texels t = frames.next()[0];
      for (size_t k = 0; k < t.rgba.size(); ++k) ASSERT_TRUE(std::isfinite(t.rgba[k])) << demo << " frame " << f;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, TemporalFog, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
