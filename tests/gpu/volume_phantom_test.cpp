// The volume phantom (passes/volume/volume_phantom.cpp) on both backends against its CPU
// twin, which compiles the shader's own text (physics/volume_phantom.h): every texel of both
// variants within one half-float step of the twin's density (relative 2^-10, plus 1e-6: the
// GPU's conversion may round either way); the
// volume is cached.
#include <cmath>
#include <string>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/volume_phantom.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

namespace vp = physics::volume_phantom;

constexpr const char* kPhantomConfig = R"({ "output": { "size": [8, 8] },
  "scene": { "camera": { "position": [0, 1, 5], "target": [0, 1, 0] } },
  "graph": { "passes": [ { "name": "phantom", "type": "volume_phantom", "params": { "size": 16, "radius": 0.35, "shell": 0.1 } } ],
             "outputs": ["phantom.density"] } })";

class VolumePhantom : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(std::vector<std::string> variants = {}) {
    return load_config_text("volume_phantom.json", kPhantomConfig, registry_, {.variants = std::move(variants)});
  }
  PassRegistry registry_;
};

// The largest |GPU − twin| over the volume, in half-float steps at the twin's value.
double worst_rounding(const Texels& t, int phantom) {
  double worst = 0;
  for (uint32_t z = 0; z < t.depth; ++z)
    for (uint32_t y = 0; y < t.height; ++y)
      for (uint32_t x = 0; x < t.width; ++x) {
        const glm::vec3 p = (glm::vec3(x, y, z) + 0.5f) / glm::vec3(t.width, t.height, t.depth);
        const double want = vp::volume_phantom_density(phantom, p, 0.35f, 0.1f);
        const double gpu = t.rgba[4 * ((size_t(z) * t.height + y) * t.width + x)];
        worst = std::max(worst, std::abs(gpu - want) / (std::abs(want) * std::ldexp(1.0, -10) + 1e-6));
      }
  return worst;
}

TEST_P(VolumePhantom, EveryTexelIsTheTwinsToOneHalfFloatStep) {
  for (const auto& [variant, code] : {std::pair{"sphere", VOLUME_PHANTOM_SPHERE}, std::pair{"shells", VOLUME_PHANTOM_SHELLS}}) {
    const LoadedConfig config = load({std::string("phantom=") + variant});
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    const Texels density = executor.read_output(0);
    ASSERT_EQ(density.depth, 16u);
    EXPECT_LE(worst_rounding(density, code), 1.0) << variant;
  }
}

TEST_P(VolumePhantom, ASecondFrameKeepsTheVolume) {
  const LoadedConfig config = load();
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  ASSERT_EQ(executor.timings().size(), 1u);
  EXPECT_FALSE(executor.timings()[0].cached);
  executor.run_frame();
  EXPECT_TRUE(executor.timings()[0].cached) << "the phantom depends on its variant and parameters alone";
}

INSTANTIATE_TEST_SUITE_P(Backends, VolumePhantom, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
