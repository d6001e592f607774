// The cloud march under stress (Schneider & Vos 2015), both backends: the camera below, inside, above
// and level with the layer's boundaries, the view ray tangent to the layer's top; coverage
// 0 and 1; extinction from 1e-6 to the declared maximum (10 /m) in factors of 100; steps 1
// and 1024 with one light sample. Every pixel of both outputs finite, T in [0, 1], radiance
// ≥ 0. Small sizes (32 × 18, noise 16³/16³/16²) keep it quick on lavapipe.
#include <cmath>
#include <string>
#include <vector>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

// Earth's radius and the default layer (1500–4000 m): where a view ray is tangent to the top.
constexpr double kPlanetRadius = 6360000, kLayerTop = 4000, kAbove = 6000;

struct View {
  std::string name, position, target;
};

// The dip below the horizon at which a ray from kAbove grazes the layer's top sphere.
std::string tangent_target() {
  const double dip = std::acos((kPlanetRadius + kLayerTop) / (kPlanetRadius + kAbove));
  return "[0, " + std::to_string(kAbove - std::tan(dip)) + ", -1]";
}

std::vector<View> views() {
  return {{"from the ground, up", "[0, 2, 0]", "[0, 3, -0.3]"},
          {"from the ground, at the horizon", "[0, 2, 0]", "[0, 2, -1]"},
          {"at the layer's bottom, level", "[0, 1500, 0]", "[0, 1500, -1]"},
          {"inside the layer, level", "[0, 2500, 0]", "[0, 2500, -1]"},
          {"at the layer's top, level (tangent)", "[0, 4000, 0]", "[0, 4000, -1]"},
          {"above, 45° down", "[0, 6000, 0]", "[0, 5999, -1]"},
          {"above, tangent to the top", "[0, 6000, 0]", tangent_target()}};
}

std::string config_text(const View& v, const std::string& clouds, const std::string& params) {
  return R"({ "output": { "size": [32, 18] },
  "scene": { "camera": { "position": )" + v.position + R"(, "target": )" + v.target + R"(, "fov_y_deg": 50 },
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "name": "box", "shape": "box", "material": "grey", "size": [1, 1, 1], "transform": { "translate": [0, 0, 6000] } } ],
    "lights": [ { "name": "sun", "type": "directional", "direction": [0.3, -0.8, -0.5], "irradiance": [3, 3, 3] } ],
    "clouds": { )" + clouds + R"( } },
  "graph": { "passes": [
      { "name": "lit", "type": "scene" },
      { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 16, "detail_size": 16, "curl_size": 16 } },
      { "name": "march", "type": "cloud_march", "params": )" + params + R"(,
        "inputs": { "depth": "lit.depth", "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl" } } ],
    "outputs": ["march.clouds", "march.transmittance"] } })";
}

class CloudMarchStress : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  // Runs one frame and checks both outputs: rgb radiance finite and ≥ 0, T finite in [0, 1]
  // (clouds.a and transmittance.rgb). Returns the mean transmittance, so a case is seen to vary.
  double run_and_check(const View& v, const std::string& clouds, const std::string& params) {
    const std::string what = v.name + " | " + clouds + " | " + params;
    const LoadedConfig config = load_config_text("cloud_stress.json", config_text(v, clouds, params), registry_);
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    const Texels clouds_image = executor.read_output(0), transmittance = executor.read_output(1);
    double sum = 0;
    for (size_t i = 0; i < clouds_image.rgba.size(); i += 4) {
      for (size_t c = 0; c < 3; ++c) {
        const float radiance = clouds_image.rgba[i + c], t = transmittance.rgba[i + c];
        EXPECT_TRUE(std::isfinite(radiance) && radiance >= 0.0f) << what << " pixel " << i / 4 << " radiance " << radiance;
        EXPECT_TRUE(std::isfinite(t) && t >= 0.0f && t <= 1.0f) << what << " pixel " << i / 4 << " transmittance " << t;
      }
      const float t = clouds_image.rgba[i + 3];
      EXPECT_TRUE(std::isfinite(t) && t >= 0.0f && t <= 1.0f) << what << " pixel " << i / 4 << " clouds.a " << t;
      sum += t;
    }
    return sum / double(clouds_image.rgba.size() / 4);
  }
  PassRegistry registry_;
};

const std::vector<std::string> kMarchParams = {R"({ "steps": 1, "light_steps": 1 })",
                                               R"({ "steps": 1024, "light_steps": 1 })", "{}"};

TEST_P(CloudMarchStress, EveryViewAndExtinctionAtFullCoverageStaysFiniteWithTInRange) {
  for (const View& v : views())
    for (const char* extinction : {"1e-6", "1e-4", "0.01", "1", "10"})
      for (const std::string& params : kMarchParams)
        run_and_check(v, std::string(R"("coverage": 1, "extinction": )") + extinction, params);
}

// So the checks above see cloud: at full coverage and the maximum extinction the view
// from inside the layer is nearly opaque, and at coverage 0 every view is clear.
TEST_P(CloudMarchStress, CoverageZeroIsClearAndFullCoverageIsOpaqueFromInside) {
  for (const View& v : views())
    for (const std::string& params : kMarchParams)
      EXPECT_EQ(run_and_check(v, R"("coverage": 0)", params), 1.0) << v.name << " " << params;
  EXPECT_LT(run_and_check(views()[3], R"("coverage": 1, "extinction": 10)", "{}"), 0.5);
}

INSTANTIATE_TEST_SUITE_P(Backends, CloudMarchStress, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
