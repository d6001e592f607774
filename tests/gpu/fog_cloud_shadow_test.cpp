// Cloud shadows in the fog (cloud_shadow_map → froxel_scatter and raymarch_fog), on both
// backends: a homogeneous fog lit by the sun alone under a cloud layer, the froxel grid and
// the march 16 m deep so every sample lies within a fraction of one of the map's texels. The
// light each froxel scatters (froxel_scatter) or each pixel's ray gathers (raymarch_fog) with
// the map wired is the light without it times exp(−τ) of the map at the point where the
// sun's ray from the camera meets the layer's bottom (two fp16 steps, plus what τ's slope
// over 16 m can move); grey (the same factor in r, g and b); coverage 0 bit for bit as
// without the map; and the same with a shadow map of the sun wired as well (another
// permutation of each pass's shader).
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/clouds/cloud_shadow_view.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/cloud_shadow_twin.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr double kFogGridDepth = 16;     // m: the froxel grid's far plane
constexpr double kCloudMapExtent = 40000;  // m: cloud_shadow_map's default
constexpr int kCloudMapSize = 64;

// The two fog techniques' passes `clouded` (reading the map) and `bare` (not), the froxel
// grid's or the march's first output.
std::string fog_passes(const std::string& technique, const std::string& shadow_inputs) {
  const std::string clouded_inputs = R"("cloud_shadow": "shadow.optical_depth", "cloud_shadow_view": "shadow.view")" + shadow_inputs;
  if (technique == "raymarch_fog") {
    const std::string march = R"("type": "raymarch_fog", "params": { "max_distance": 16, "steps": 32, "jitter": false })";
    return R"({ "name": "lit", "type": "scene" },
    { "name": "clouded", )" + march + R"(, "inputs": { "depth": "lit.depth", )" + clouded_inputs + R"( } },
    { "name": "bare", )" + march + R"(, "inputs": { "depth": "lit.depth")" + shadow_inputs + R"( } } ],
    "outputs": ["clouded.fog_scattering", "bare.fog_scattering", "shadow.optical_depth"] } })";
  }
  const std::string media = R"("media_scattering": "fog_media.media_scattering", "media_emission": "fog_media.media_emission", "frame": "fog_media.frame")";
  return R"({ "name": "fog_media", "type": "froxel_voxelize", "params": { "tile": 4, "slices": 8, "near": 0.5, "far": 16, "distribution": "linear", "jitter": false } },
    { "name": "clouded", "type": "froxel_scatter", "inputs": { )" + media + ", " + clouded_inputs + R"( } },
    { "name": "bare", "type": "froxel_scatter", "inputs": { )" + media + shadow_inputs + R"( } } ],
    "outputs": ["clouded.in_scatter", "bare.in_scatter", "shadow.optical_depth"] } })";
}

std::string fog_under_clouds(const std::string& technique, const std::string& clouds, bool with_shadow_map) {
  const std::string sun_shadow = with_shadow_map ? R"({ "name": "sun_shadow", "type": "shadow_map", "params": { "light": 0, "resolution": 256 } },)" : "";
  const std::string shadow_inputs = with_shadow_map ? R"(, "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view")" : "";
  return R"({ "output": { "size": [16, 16] },
  "scene": { "camera": { "position": [300, 2, -200], "target": [300, 2.5, -201], "fov_y_deg": 60 },
    "background": { "radiance": [0, 0, 0] },
    "lights": [ { "name": "sun", "type": "directional", "direction": [0.3, -0.8, -0.5], "irradiance": [3, 3, 3] } ],
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "shape": "plane", "size": [100, 1, 100], "material": "grey", "transform": { "translate": [300, -50, -200] } } ],
    "media": { "fog": { "albedo": [1, 1, 1], "extinction": [0.02, 0.02, 0.02], "g": 0 } },
    "clouds": { )" + clouds + R"( } },
  "graph": { "passes": [
    { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 32, "detail_size": 16, "curl_size": 32 } },
    { "name": "shadow", "type": "cloud_shadow_map", "params": { "size": 64 },
      "inputs": { "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl" } },)" + sun_shadow + R"(
    )" + fog_passes(technique, shadow_inputs);
}

struct FogRun {
  Texels clouded, bare, tau;
  Scene scene;
};

class FogCloudShadow : public OnEachBackend<std::tuple<Backend, const char*>> {
 protected:
  Backend backend() const override { return std::get<0>(GetParam()); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  FogRun run(const std::string& clouds, bool with_shadow_map) {
    const LoadedConfig config =
        load_config_text("fog_cloud_shadow.json", fog_under_clouds(std::get<1>(GetParam()), clouds, with_shadow_map), registry_);
    FogRun r;
    r.scene = config.config.scene;
    Executor executor(device(), config.graph, &r.scene, {});
    executor.run_frame();
    r.clouded = executor.read_output(0), r.bare = executor.read_output(1), r.tau = executor.read_output(2);
    return r;
  }
  PassRegistry registry_;
};

void expect_dimmed_by_the_map(const FogRun& r) {
  const gpu::CloudShadowView view = cloud_shadow_view(r.scene, kCloudMapExtent, kCloudMapSize);
  const auto [u, v] = cloud_shadow_map_uv(view, r.scene.camera.position);
  const double expected = std::exp(-cloud_shadow_tau_at(r.tau, u, v));
  // The grid reaches kFogGridDepth from the camera: τ's slope over a texel, scaled to that.
  const double texel = 1.0 / kCloudMapSize, reach = kFogGridDepth / (kCloudMapExtent / kCloudMapSize);
  const double slope = std::max(std::abs(std::exp(-cloud_shadow_tau_at(r.tau, u + texel, v)) - expected), std::abs(std::exp(-cloud_shadow_tau_at(r.tau, u, v + texel)) - expected));
  ASSERT_LT(expected, 0.95) << "the fog must be under some cloud (so the check could fail)";
  ASSERT_GT(expected, 0.02) << "and not under so much that nothing is left to compare";
  int lit = 0;
  for (size_t p = 0; p < r.bare.rgba.size(); p += 4) {
    for (size_t c = 0; c < 3; ++c) {
      const double bare = r.bare.rgba[p + c], clouded = r.clouded.rgba[p + c];
      if (bare <= 0) {
        ASSERT_EQ(clouded, 0.0f) << "texel " << p / 4;
        continue;
      }
      ++lit;
      EXPECT_NEAR(clouded, bare * expected, fp16_steps(bare * expected) + 2 * reach * slope * bare) << "texel " << p / 4 << " channel " << c;
    }
  }
  EXPECT_GT(lit, 100);
}

TEST_P(FogCloudShadow, TheFogUnderTheCloudsIsDimmedByExpMinusTau) {
  expect_dimmed_by_the_map(run(R"("coverage": 0.9, "extinction": 0.002, "wind": [0, 0, 0])", false));
}

TEST_P(FogCloudShadow, TheSameWithTheSunsShadowMapToo) {
  expect_dimmed_by_the_map(run(R"("coverage": 0.9, "extinction": 0.002, "wind": [0, 0, 0])", true));
}

TEST_P(FogCloudShadow, CoverageZeroIsTheFogWithoutTheMapBitForBit) {
  const FogRun r = run(R"("coverage": 0)", false);
  EXPECT_EQ(r.clouded.rgba, r.bare.rgba);
}

INSTANTIATE_TEST_SUITE_P(Techniques, FogCloudShadow,
                         ::testing::Combine(::testing::ValuesIn(gpu_backends()), ::testing::Values("froxel_scatter", "raymarch_fog")),
                         [](const ::testing::TestParamInfo<std::tuple<Backend, const char*>>& info) {
                           return std::string(std::get<1>(info.param)) + "_" + std::string(backend_name(std::get<0>(info.param)));
                         });

}  // namespace
}  // namespace volgraph::testing
