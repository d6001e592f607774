// The cloud noise pass (passes/clouds/cloud_noise.cpp) on both backends against its CPU
// twin, which compiles the shader's own text (physics/cloud_noise.h): every texel of the
// three textures within one 8-bit step of the twin's value rounded to 8 bits (the GPU's
// float arithmetic and conversion may round the other way); the textures are cached; a
// scene without clouds culls the pass.
#include <cmath>
#include <string>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/cloud_noise.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

namespace cn = physics::cloud_noise;

// The noise textures alone at small sizes (no image: not a shipped config); the cloud layer's
// presence is what the pass needs.
constexpr const char* kConfig = R"({ "output": { "size": [16, 16] },
  "scene": { "camera": { "position": [0, 1, 5], "target": [0, 1, 0] }, "clouds": {} },
  "graph": { "passes": [ { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 16, "detail_size": 8, "curl_size": 16 } } ],
             "outputs": ["noise.shape", "noise.detail", "noise.curl"] } })";

class CloudNoise : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(std::vector<std::string> sets = {}) {
    return load_config_text("cloud_noise.json", kConfig, registry_, {.sets = std::move(sets)});
  }
  PassRegistry registry_;
};

// The largest |GPU − twin| over a texture, in 8-bit steps; `twin(x, y, z)` the twin's texel.
template <typename Twin>
double worst_steps(const Texels& t, Twin twin) {
  double worst = 0;
  for (uint32_t z = 0; z < t.depth; ++z) {
    for (uint32_t y = 0; y < t.height; ++y) {
      for (uint32_t x = 0; x < t.width; ++x) {
        const glm::vec4 want = twin(x, y, z);
        for (int c = 0; c < 4; ++c) {
          const double gpu = t.rgba[4 * ((size_t(z) * t.height + y) * t.width + x) + size_t(c)];
          worst = std::max(worst, std::abs(gpu * 255 - std::round(double(want[c]) * 255)));
        }
      }
    }
  }
  return worst;
}

TEST_P(CloudNoise, EveryTexelIsTheTwinsTo8Bits) {
  const LoadedConfig config = load({"noise.seed=7"});
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  const Texels shape = executor.read_output(0), detail = executor.read_output(1), curl = executor.read_output(2);
  ASSERT_EQ(shape.depth, 16u);
  ASSERT_EQ(detail.depth, 8u);
  ASSERT_EQ(curl.width, 16u);
  const auto centre = [](uint32_t i, uint32_t n) { return (float(i) + 0.5f) / float(n); };
  EXPECT_LE(worst_steps(shape, [&](uint32_t x, uint32_t y, uint32_t z) {
              return cn::cloud_shape_texel(glm::vec3(centre(x, 16), centre(y, 16), centre(z, 16)), 7u);
            }), 1.0);
  EXPECT_LE(worst_steps(detail, [&](uint32_t x, uint32_t y, uint32_t z) {
              return cn::cloud_detail_texel(glm::vec3(centre(x, 8), centre(y, 8), centre(z, 8)), 7u);
            }), 1.0);
  EXPECT_LE(worst_steps(curl, [&](uint32_t x, uint32_t y, uint32_t) {
              return cn::cloud_curl_texel(glm::vec2(centre(x, 16), centre(y, 16)), 1.0f / 16.0f, 7u);
            }), 1.0);
}

TEST_P(CloudNoise, ASecondFrameKeepsTheTextures) {
  const LoadedConfig config = load();
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  ASSERT_EQ(executor.timings().size(), 1u);
  EXPECT_FALSE(executor.timings()[0].cached);
  const Texels first = executor.read_output(0);
  executor.run_frame();
  EXPECT_TRUE(executor.timings()[0].cached) << "the noise depends on its seed and sizes alone";
  EXPECT_EQ(executor.read_output(0).rgba, first.rgba);
}

TEST_P(CloudNoise, AnotherSeedGivesOtherNoise) {
  const auto shape_of = [&](const std::string& seed) {
    const LoadedConfig config = load({"noise.seed=" + seed});
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    return executor.read_output(0).rgba;
  };
  EXPECT_NE(shape_of("1"), shape_of("2"));
}

TEST_P(CloudNoise, ASceneWithoutCloudsMakesNoNoise) {
  const LoadedConfig config = load_config_text("no_clouds.json", R"({ "output": { "size": [16, 16] },
    "scene": { "camera": { "position": [0, 1, 5], "target": [0, 1, 0] } },
    "graph": { "passes": [ { "name": "noise", "type": "cloud_noise" } ], "outputs": ["noise.curl"] } })", registry_);
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  EXPECT_TRUE(executor.timings().empty()) << "cloud_noise needs a cloud layer: culled";
}

INSTANTIATE_TEST_SUITE_P(Backends, CloudNoise, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
