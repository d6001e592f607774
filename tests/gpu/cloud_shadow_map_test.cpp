// cloud_shadow_map (passes/clouds/cloud_shadow_map.cpp) and the scene's `cloud_shadow` on
// both backends: coverage 0 → τ = 0 and the scene bit for bit as without the input; τ
// against the CPU twin (reference/clouds.cpp's density, the same midpoint rule over the
// same placement, cloud_shadow_view()) and under the slab bound σt·thickness/sun_y; the
// ground under the map = the unshadowed ground × exp(−τ); finite with the sun near and below
// the horizon at extinction 10.
#include <algorithm>
#include <cmath>
#include <string>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/clouds/cloud_shadow_view.h"
#include "passes/passes.h"
#include "reference/clouds.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/cloud_shadow_twin.h"

namespace volgraph::testing {
namespace {

struct ShadowCase {
  std::string sun = "[0.3, -0.8, -0.5]";
  std::string clouds = R"("coverage": 0.6, "wind": [0, 0, 0])";
  std::string params = R"({ "size": 32, "extent": 40000, "steps": 32 })";
  bool shadow_map = false;  // the scenes also read a shadow map of the sun (another of the scene's shaders)
};

// The ground seen from 10 m straight down through a 10° lens (a 1.7 m patch: one point for a
// 1250 m texel), the map, and the scene twice: `lit` reads the map, `bare` does not.
// Outputs: the map's τ, lit's and bare's colours.
std::string shadow_config_text(const ShadowCase& k) {
  const std::string sun_shadow = k.shadow_map ? R"({ "name": "sun_shadow", "type": "shadow_map" },)" : "";
  const std::string shadow_inputs = k.shadow_map ? R"("shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view")" : "";
  return R"({ "output": { "size": [8, 8] },
  "scene": { "camera": { "position": [0, 10, 0], "target": [0, 0, -0.01], "fov_y_deg": 10 },
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "name": "ground", "shape": "plane", "material": "grey", "size": [100, 1, 100] } ],
    "lights": [ { "name": "sun", "type": "directional", "direction": )" + k.sun + R"(, "irradiance": [3, 3, 3] } ],
    "clouds": { )" + k.clouds + R"( } },
  "graph": { "passes": [
      { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 32, "detail_size": 16, "curl_size": 32 } },
      { "name": "shadow", "type": "cloud_shadow_map", "params": )" + k.params + R"(,
        "inputs": { "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl" } },
      )" + sun_shadow + R"(
      { "name": "lit", "type": "scene", "inputs": { "cloud_shadow": "shadow.optical_depth", "cloud_shadow_view": "shadow.view")" +
         (k.shadow_map ? ", " + shadow_inputs : "") + R"( } },
      { "name": "bare", "type": "scene", "inputs": { )" + shadow_inputs + R"( } } ],
    "outputs": ["shadow.optical_depth", "lit.color", "bare.color"] } })";
}

struct ShadowRun {
  LoadedConfig config;
  Texels tau, lit, bare;
};

class CloudShadowMap : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  ShadowRun run(const ShadowCase& k) {
    ShadowRun r{load_config_text("cloud_shadow_map.json", shadow_config_text(k), registry_), {}, {}, {}};
    Executor executor(device(), r.config.graph, &r.config.config.scene, {});
    executor.run_frame();
    r.tau = executor.read_output(0), r.lit = executor.read_output(1), r.bare = executor.read_output(2);
    return r;
  }
  PassRegistry registry_;
};

float shadow_tau_at(const Texels& t, uint32_t i, uint32_t j) { return t.rgba[(size_t(j) * t.width + i) * 4]; }

TEST_P(CloudShadowMap, TheCaseCastsShadow) {  // so the identities below could fail
  const ShadowRun r = run({});
  float largest = 0;
  for (size_t i = 0; i < r.tau.rgba.size(); i += 4) largest = std::max(largest, r.tau.rgba[i]);
  EXPECT_GT(largest, 1.0f);
}

TEST_P(CloudShadowMap, CoverageZeroIsNoShadowAndTheSceneBitForBit) {
  ShadowCase k;
  k.clouds = R"("coverage": 0)";
  const ShadowRun r = run(k);
  for (size_t i = 0; i < r.tau.rgba.size(); i += 4) ASSERT_EQ(r.tau.rgba[i], 0.0f) << "texel " << i / 4;
  EXPECT_EQ(r.lit.rgba, r.bare.rgba);
}

// τ of a few texels against the CPU twin: reference::CloudReference's density (the same text,
// the same rgba8 textures) by the same midpoint rule from the same point, over the same
// length (to the layer's top sphere). And the slab bound: ρ ≤ 1, so τ ≤ σt·thickness/sun_y
// (the path through a flat slab; the sphere's is shorter by < 1e-3 at 20 km).
TEST_P(CloudShadowMap, OpticalDepthMatchesTheCpuTwinAndTheSlabBound) {
  const ShadowRun r = run({});
  const Scene& scene = r.config.config.scene;
  const int size = int(r.tau.width);
  const gpu::CloudShadowView view = cloud_shadow_view(scene, 40000, size);
  const reference::CloudReference twin(scene, reference::cloud_reference_settings(r.config.graph, r.config.params));
  const Vec3 to_sun{view.to_sun[0], view.to_sun[1], view.to_sun[2]};
  const CloudLayer& layer = *scene.clouds;
  const double slab = layer.extinction * (layer.top_altitude - layer.bottom_altitude) / to_sun[1];
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) ASSERT_LE(shadow_tau_at(r.tau, uint32_t(i), uint32_t(j)), slab * 1.001) << i << ", " << j;
  int compared = 0;
  for (int j = 1; j < size; j += 5) {
    for (int i = 2; i < size; i += 7) {
      const Vec3 q{view.plane[0] + ((i + 0.5) / size - 0.5) * view.plane[3], view.plane[1],
                   view.plane[2] + ((j + 0.5) / size - 0.5) * view.plane[3]};
      // The top sphere from q along to_sun (the planet's centre below the origin, Earth's radius).
      const double radius = 6360e3, top = radius + layer.top_altitude;
      const Vec3 oc{q[0], q[1] + radius, q[2]};
      const double b = oc[0] * to_sun[0] + oc[1] * to_sun[1] + oc[2] * to_sun[2];
      const double c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - top * top;
      const double length = -b + std::sqrt(b * b - c);
      const int steps = 32;
      double tau = 0;
      for (int s = 0; s < steps; ++s) {
        const double t = (s + 0.5) * length / steps;
        tau += layer.extinction * twin.density({q[0] + t * to_sun[0], q[1] + t * to_sun[1], q[2] + t * to_sun[2]}) * length / steps;
      }
      const double gpu = shadow_tau_at(r.tau, uint32_t(i), uint32_t(j));
      // fp16 (2⁻¹¹ relative) and the filtering's fixed-point weights on the noise textures.
      EXPECT_NEAR(gpu, tau, 0.02 * tau + 0.01) << "texel " << i << ", " << j;
      compared += tau > 0.1;
    }
  }
  EXPECT_GT(compared, 2) << "too few shadowed texels compared";
}

// The ground's radiance with the map = without it × exp(−τ) at the ground point's uv
// (carried toward the sun onto the bottom plane): two fp16 steps, plus what 1 % of a texel
// of τ's slope can move (the patch seen is 1.7 m of a 1250 m texel).
void expect_ground_dimmed_by_the_map(const ShadowRun& r);

// With a shadow map of the sun too (the scene's other shader): the same.
TEST_P(CloudShadowMap, TheGroundUnderTheMapIsTheUnshadowedTimesExpMinusTau) {
  for (const bool shadow_map : {false, true}) {
    SCOPED_TRACE(shadow_map ? "with a shadow map" : "without a shadow map");
    ShadowCase k;
    k.shadow_map = shadow_map;
    expect_ground_dimmed_by_the_map(run(k));
  }
}

void expect_ground_dimmed_by_the_map(const ShadowRun& r) {
  const gpu::CloudShadowView view = cloud_shadow_view(r.config.config.scene, 40000, int(r.tau.width));
  const double s = (view.plane[1] - 0.0) / view.to_sun[1];  // the ground point ≈ the origin
  const double u = (s * view.to_sun[0] - view.plane[0]) / view.plane[3] + 0.5, v = (s * view.to_sun[2] - view.plane[2]) / view.plane[3] + 0.5;
  ASSERT_TRUE(u > 0 && u < 1 && v > 0 && v < 1);
  const double expected = std::exp(-cloud_shadow_tau_at(r.tau, u, v));
  const double spread = std::abs(std::exp(-cloud_shadow_tau_at(r.tau, u + 1.0 / r.tau.width, v)) - expected) +
                        std::abs(std::exp(-cloud_shadow_tau_at(r.tau, u, v + 1.0 / r.tau.height)) - expected);
  for (size_t p = 0; p < r.lit.rgba.size(); p += 4) {
    const double bare = r.bare.rgba[p], lit = r.lit.rgba[p];
    ASSERT_GT(bare, 0.1) << "pixel " << p / 4 << " sees the ground";
    EXPECT_NEAR(lit, bare * expected, 2 * std::ldexp(bare, -10) + 0.02 * spread * bare) << "pixel " << p / 4;
  }
  EXPECT_LT(expected, 0.99) << "the point under test is shadowed (so the check could fail)";
}

// The sun 1° up and 6° below the horizon at extinction 10: every τ and pixel finite, τ ≥ 0;
// below, τ is large (the planet's shadow) and the sun adds nothing.
TEST_P(CloudShadowMap, FiniteWithTheSunAtAndBelowTheHorizon) {
  struct Sun {
    const char* direction;
    bool below;
  };
  for (const Sun& sun : {Sun{"[0.3, -0.0175, -0.95]", false}, Sun{"[0.3, 0.1, -0.95]", true}}) {
    ShadowCase k;
    k.sun = sun.direction;
    k.clouds = R"("coverage": 1, "extinction": 10, "wind": [0, 0, 0])";
    const ShadowRun r = run(k);
    for (size_t i = 0; i < r.tau.rgba.size(); i += 4) {
      ASSERT_TRUE(std::isfinite(r.tau.rgba[i]) && r.tau.rgba[i] >= 0) << sun.direction << " texel " << i / 4;
      if (sun.below) ASSERT_GE(r.tau.rgba[i], 1e4f) << "below the horizon, texel " << i / 4;
    }
    for (float v : r.lit.rgba) ASSERT_TRUE(std::isfinite(v)) << sun.direction;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, CloudShadowMap, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
