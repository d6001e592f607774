// The froxel chain (froxel_voxelize → froxel_scatter → scatter_integrate → froxel_apply)
// together on both backends:
// - no lights, no absorption, no emission: nothing appears (exactly 0);
// - stress (σt up to 1e4, g = ±0.999, a light at the camera, a zero-size volume, a grid
//   from 1 mm to 100 km, an opacity shadow map over a zero-size volume): no NaN or Inf in
//   any intermediate volume, transmittance in [0, 1];
// - without a medium the four passes are culled and the image is the scene's own.
// Each pass's own cases: froxel_scatter_test.cpp (volumetric self-shadowing),
// scatter_integrate_test.cpp (Beer–Lambert, Hillaire's exact case), opacity_shadow_map_test.cpp;
// froxel_voxelize_test.cpp. The fixture is froxel_fog.h.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/gpu/froxel_fog.h"

namespace volgraph::testing {
namespace {

class FroxelFog : public FroxelFogFixture {};

TEST_P(FroxelFog, NothingAppearsWithoutLightsAbsorptionOrEmission) {
  const Texels t = render(load(FogCase{}));
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    for (size_t ch = 0; ch < 3; ++ch) ASSERT_EQ(t.rgba[i + ch], 0.0f) << "texel " << i / 4;
  }
}

TEST_P(FroxelFog, StressLimitsLeaveNoNanOrInfInAnyVolume) {
  for (const char* m : kStressMedia) {
    FogCase c;
    c.media = m;
    c.lights = kStressLights;
    c.background = "[1, 1, 1]";
    c.opacity_shadow_map = true;  // the directional light's volumetric shadows by the map, the point light's by no march
    c.grid = R"({ "slices": 16, "near": 0.001, "far": 100000, "distribution": "exponential", "jitter": false })";
    LoadedConfig config = load(c);
    for (uint32_t r = 0; r < config.graph.resources.size(); ++r) {  // keep every volume to read it back (as --dump does)
      const GraphResource& resource = config.graph.resources[r];
      if (resource.desc.kind == ResourceKind::texture3d) config.graph.outputs.push_back({r, uint32_t(resource.version_writers.size() - 1)});
    }
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    for (uint32_t r = 0; r < config.graph.resources.size(); ++r) {
      const ResourceDesc& d = config.graph.resources[r].desc;
      if (d.kind != ResourceKind::texture3d && d.name != "out.output") continue;
      const Texels t = executor.read_texture(r);
      for (size_t k = 0; k < t.rgba.size(); ++k) ASSERT_TRUE(std::isfinite(t.rgba[k])) << d.name << " value " << k << " of " << m;
      if (d.name != "fog_integral.integrated_transmittance") continue;
      for (size_t k = 0; k < t.rgba.size(); k += 4) {
        for (size_t ch = 0; ch < 3; ++ch) {
          ASSERT_GE(t.rgba[k + ch], 0.0f) << m;
          ASSERT_LE(t.rgba[k + ch], 1.0f) << m;
        }
      }
    }
  }
}

TEST_P(FroxelFog, WithoutAMediumTheFogPassesAreCulledAndTheSceneIsUntouched) {
  FogCase with;
  with.media = R"({ "fog": { "sigma_s": [0, 0, 0], "sigma_a": [0, 0, 0] } })";  // no medium at all
  with.background = "[0.25, 0.5, 1]";
  const LoadedConfig config = load(with);
  Executor executor(device(), config.graph, &config.config.scene, {});
  EXPECT_EQ(executor.plan().culled.size(), 4u);
  for (const CulledPass& culled : executor.plan().culled) EXPECT_EQ(culled.reason, CullReason::scene_lacks);
  executor.run_frame();
  const Texels t = executor.read_output(0);
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    ASSERT_EQ(t.rgba[i], 0.25f);
    ASSERT_EQ(t.rgba[i + 2], 1.0f);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, FroxelFog, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
