// The cloud march (passes/clouds/cloud_march.cpp) on both backends: no cloud is the
// identity, a ray that misses the layer is the identity, more extinction never more
// transmittance, every parameter at its limits finite with T in [0, 1], octaves under a
// white sun return no more than a white Lambertian slab would, a > b refused, and the pass
// culled without a cloud layer.
#include <cmath>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "graph/config/config.h"
#include "graph/diagnostics.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;

// What a case varies: the camera, the sun's direction of travel, the layer and the pass's parameters.
struct Case {
  std::string position = "[0, 2, 0]";
  std::string target = "[0, 3, -0.3]";  // up, 73° above the horizon
  std::string sun = "[0.3, -0.8, -0.5]";
  std::string irradiance = "[3, 3, 3]";
  std::string clouds = R"("coverage": 0.6)";
  std::string params = "{}";
  std::string atmosphere;  // a scene.atmosphere object, or none
};

// A 24 × 24 frame: the scene pass (one box behind the camera, for its depth), small noise
// textures, the march; outputs the march's `clouds` image (rgb radiance, a transmittance).
std::string config_text(const Case& k) {
  return R"({ "output": { "size": [24, 24] },
  "scene": { "camera": { "position": )" + k.position + R"(, "target": )" + k.target + R"(, "fov_y_deg": 50 },
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "name": "box", "shape": "box", "material": "grey", "size": [1, 1, 1], "transform": { "translate": [0, 0, 6000] } } ],
    "lights": [ { "name": "sun", "type": "directional", "direction": )" + k.sun + R"(, "irradiance": )" + k.irradiance + R"( } ],
    "clouds": { )" + k.clouds + R"( })" + (k.atmosphere.empty() ? "" : R"(, "atmosphere": )" + k.atmosphere) + R"( },
  "graph": { "passes": [
      { "name": "lit", "type": "scene" },
      { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 32, "detail_size": 16, "curl_size": 32 } },
      { "name": "march", "type": "cloud_march", "params": )" + k.params + R"(,
        "inputs": { "depth": "lit.depth", "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl" } } ],
    "outputs": ["march.clouds"] } })";
}

class CloudMarch : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  Texels run(const Case& k) {
    const LoadedConfig config = load_config_text("cloud_march.json", config_text(k), registry_);
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    return executor.read_output(0);
  }
  PassRegistry registry_;
};

double mean_channel(const Texels& t, int channel) {
  double sum = 0;
  for (size_t i = size_t(channel); i < t.rgba.size(); i += 4) sum += t.rgba[i];
  return sum / double(t.rgba.size() / 4);
}

// Every pixel exactly the identity: radiance 0, transmittance 1.
void expect_identity(const Texels& t, const std::string& what) {
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    ASSERT_EQ(t.rgba[i], 0.0f) << what << " pixel " << i / 4;
    ASSERT_EQ(t.rgba[i + 1], 0.0f) << what << " pixel " << i / 4;
    ASSERT_EQ(t.rgba[i + 2], 0.0f) << what << " pixel " << i / 4;
    ASSERT_EQ(t.rgba[i + 3], 1.0f) << what << " pixel " << i / 4;
  }
}

TEST_P(CloudMarch, TheCaseSeesCloud) {  // so the identities below could fail
  const Texels t = run({});
  EXPECT_LT(mean_channel(t, 3), 0.9);
  EXPECT_GT(mean_channel(t, 0), 0.0);
}

// With an atmosphere the sun reaches the layer through the air (its transmittance) and the
// sky lights it (its multiple-scattering radiance): a low sun is reddened by the long path,
// so the cloud's red over blue rises from the sun high to the sun 3° up (measured 0.706 →
// 0.763 on lavapipe; the sky's blue ambient holds it down) where a white sun
// without the air gives 1 for both). Finite everywhere.
TEST_P(CloudMarch, CloudLitThroughTheAtmosphereIsRedderWithTheSunLow) {
  const auto red_over_blue = [&](const char* sun) {
    Case k;
    k.sun = sun;
    k.atmosphere = R"({ "preset": "earth", "sun": { "light": "sun" } })";
    const Texels t = run(k);
    for (float v : t.rgba) EXPECT_TRUE(std::isfinite(v)) << sun;
    EXPECT_GT(mean_channel(t, 2), 0.0) << sun;
    return mean_channel(t, 0) / mean_channel(t, 2);
  };
  const double high = red_over_blue("[0.3, -0.8, -0.5]"), low = red_over_blue("[0.3, -0.052, -0.95]");
  EXPECT_GT(low, 1.04 * high) << "red/blue: sun high " << high << ", sun 3° up " << low;
}

// The jitter moves each fine sample within its step per pixel and frame: with no wind, the
// second frame differs from the first where there is cloud; without jitter the two are the
// same image (the midpoints).
TEST_P(CloudMarch, JitterMovesTheSamplesFromFrameToFrameAndOffKeepsTheMidpoints) {
  const auto two_frames = [&](const char* params) {
    Case k;
    k.clouds = R"("coverage": 0.6, "wind": [0, 0, 0])";
    k.params = params;
    const LoadedConfig config = load_config_text("cloud_march.json", config_text(k), registry_);
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    const Texels first = executor.read_output(0);
    executor.run_frame();
    return std::make_pair(first, executor.read_output(0));
  };
  const auto [on0, on1] = two_frames(R"({ "jitter": true })");
  const auto [off0, off1] = two_frames(R"({ "jitter": false })");
  EXPECT_NE(on0.rgba, on1.rgba) << "jitter on: frames 0 and 1 alike";
  EXPECT_EQ(off0.rgba, off1.rgba) << "jitter off: frames 0 and 1 differ";
  EXPECT_NE(on0.rgba, off0.rgba) << "jitter on and off alike at frame 0";
}

TEST_P(CloudMarch, CoverageZeroIsTheIdentity) {
  Case k;
  k.clouds = R"("coverage": 0)";
  expect_identity(run(k), "coverage 0");
}

TEST_P(CloudMarch, ARayBelowTheHorizonMissesTheLayer) {
  Case k;
  k.target = "[0, 1, -1]";  // 45° down: every pixel's ray meets the ground first
  k.clouds = R"("coverage": 1)";
  expect_identity(run(k), "below the horizon");
}

TEST_P(CloudMarch, MoreExtinctionNeverMoreTransmittance) {
  std::vector<Texels> images;
  for (const char* sigma : {"0.005", "0.02", "0.08", "0.32"}) {
    Case k;
    k.clouds = std::string(R"("coverage": 0.6, "extinction": )") + sigma;
    images.push_back(run(k));
  }
  for (size_t n = 1; n < images.size(); ++n) {
    EXPECT_LT(mean_channel(images[n], 3), mean_channel(images[n - 1], 3)) << "extinction step " << n;
    for (size_t i = 3; i < images[n].rgba.size(); i += 4)
      ASSERT_LE(images[n].rgba[i], images[n - 1].rgba[i] + 1e-3f) << "extinction step " << n << " pixel " << i / 4;
  }
}

TEST_P(CloudMarch, ParametersAtTheirLimitsStayFinite) {
  const std::vector<std::string> suns = {"[0.3, -0.8, -0.5]", "[0, 0, -1]", "[0, 0.4, -0.9]"};  // high, at the horizon, below
  const std::vector<std::string> params = {
      R"({ "steps": 1, "light_steps": 1, "octaves": 1 })",
      R"({ "steps": 1024, "light_steps": 64, "octaves": 8, "a": 1, "b": 1, "c": 1, "powder": true })",
      R"({ "octaves": 8, "a": 0, "b": 1, "c": 0, "g_forward": 0.998, "g_back": -0.998, "back_weight": 1 })"};
  for (const std::string& sun : suns)
    for (const std::string& p : params) {
      Case k;
      k.sun = sun;
      k.params = p;
      k.irradiance = "[1e5, 1e5, 1e5]";
      k.clouds = R"("coverage": 1, "type": 1, "extinction": 10)";
      const Texels t = run(k);
      for (size_t i = 0; i < t.rgba.size(); i += 4) {
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(t.rgba[i + size_t(c)]) && t.rgba[i + size_t(c)] >= 0) << sun << " " << p;
        ASSERT_GE(t.rgba[i + 3], 0.0f) << sun << " " << p;
        ASSERT_LE(t.rgba[i + 3], 1.0f) << sun << " " << p;
      }
    }
}

// From above the layer, looking straight down with a white sun (E = 1) overhead behind the
// camera: the light the cloud returns, octaves on, averages no more than a white Lambertian
// slab's E cosθ / π under the same sun.
TEST_P(CloudMarch, OctavesReturnNoMoreThanAWhiteLambertianSlab) {
  Case k;
  k.position = "[0, 6000, 0]";
  k.target = "[0, 5999, -0.05]";
  k.sun = "[0, -1, 0]";
  k.irradiance = "[1, 1, 1]";
  k.clouds = R"("coverage": 1, "extinction": 0.1)";
  k.params = R"({ "octaves": 3 })";
  const Texels t = run(k);
  const double returned = mean_channel(t, 0);
  EXPECT_GT(returned, 0.0);
  EXPECT_LE(returned, 1.0 / kPi);
}

TEST_P(CloudMarch, AAboveBIsRefused) {
  Case k;
  k.params = R"({ "a": 0.8, "b": 0.5 })";
  try {
    run(k);
    FAIL() << "a > b was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("a (0.8) must not exceed b (0.5)"), std::string::npos) << e.what();
  }
}

TEST_P(CloudMarch, ASceneWithoutCloudsCullsTheMarch) {
  const LoadedConfig config = load_config_text("no_clouds.json", R"({ "output": { "size": [16, 16] },
    "scene": { "camera": { "position": [0, 1, 5], "target": [0, 1, 0] }, "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
               "objects": [ { "name": "box", "shape": "box", "material": "grey", "size": [1, 1, 1] } ] },
    "graph": { "passes": [ { "name": "lit", "type": "scene" },
        { "name": "noise", "type": "cloud_noise" },
        { "name": "march", "type": "cloud_march",
          "inputs": { "depth": "lit.depth", "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl" } } ],
      "outputs": ["lit.color", "march.clouds"] } })", registry_);
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  for (const PassTiming& timing : executor.timings()) EXPECT_NE(timing.type, "cloud_march") << "culled without a cloud layer";
  EXPECT_FALSE(executor.timings().empty()) << "the scene pass still runs";
}

INSTANTIATE_TEST_SUITE_P(Backends, CloudMarch, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
