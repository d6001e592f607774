// Cross-backend agreement: every shipped config rendered at 64x36 on Vulkan and on
// WebGPU (Dawn over the same lavapipe) gives the same linear image. The composite pass
// runs its `none` variant (linear radiance, no tone map), so differences are not
// compressed by a curve. Metric (tests/support/image_compare.h), WebGPU against Vulkan:
// relative mean absolute error Σ|w − v| / Σ|v| over RGB, and the fraction of pixels with
// a channel off by more than 5 % of max(|v|, mean |v|). Both backends run the same
// SPIR-V on the same rasteriser (Dawn translates it through Tint for lavapipe's Vulkan),
// so the bounds are tight: on lavapipe (both backends' device llvmpipe) every config
// bit-identical, as measured (relative mean error 0, no outlier; README "Tests");
// elsewhere graphs without rasterisation bit-identical, rasterised ones relative mean
// error ≤ 1e-5 and outliers ≤ 0.1 % (room for a Dawn or driver whose translation rounds
// an edge pixel differently).
#include <algorithm>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/shipped_configs.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

// The config at the test size with every composite pass linear.
LoadedConfig load_linear(const PassRegistry& registry, const std::string& config) {
  Overrides o;
  o.size = kConfigTestSize;
  const LoadedConfig probe = load_config(config_path(config), registry, o);
  for (const GraphPass& p : probe.graph.passes) {
    if (p.decl->name == "composite") o.variants.push_back(p.name + "=none");
  }
  return load_config(config_path(config), registry, o);
}

// Whether every pass that runs is compute or transfer (no rasterisation).
bool compute_only(const LoadedConfig& c) {
  const Plan plan = compile(c.graph, {});
  return std::ranges::all_of(plan.order, [&](const PlannedPass& p) { return c.graph.passes[p.pass].kind != PassKind::graphics ||
                                                                            c.graph.passes[p.pass].decl->name == "clear"; });
}

struct Rendered {
  Texels texels;
  rhi::AdapterInfo adapter;
};

Rendered render_on(Backend backend, const LoadedConfig& c) {
  std::unique_ptr<GpuUnderTest> gpu = create_gpu(backend);
  Rendered rendered{.adapter = gpu->device().info()};
  Texels& texels = rendered.texels;
  {
    Executor executor(gpu->device(), c.graph, &c.config.scene, {});
    executor.run_frame();
    texels = executor.read_output(0);
  }
  const std::vector<std::string> messages = gpu->finish();
  EXPECT_TRUE(messages.empty()) << backend_name(backend) << " validation:\n" << joined_messages(messages);
  return rendered;
}

bool on_llvmpipe(const rhi::AdapterInfo& adapter) { return adapter.device.find("llvmpipe") != std::string::npos; }

class CrossBackend : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { register_builtin_passes(registry_); }
  PassRegistry registry_;
};

TEST_P(CrossBackend, LinearOutputsAgree) {
  const LoadedConfig c = load_linear(registry_, GetParam());
  const Rendered on_vulkan = render_on(Backend::vulkan, c);
  const Rendered on_webgpu = render_on(Backend::webgpu, c);
  const Texels &vulkan = on_vulkan.texels, &webgpu = on_webgpu.texels;
  ASSERT_EQ(webgpu.width, vulkan.width);
  ASSERT_EQ(webgpu.height, vulkan.height);
  const ImageDifference d = compare_images(webgpu.rgba, vulkan.rgba);
  std::printf("%s: webgpu (%s) vs vulkan (%s): %s\n", GetParam().c_str(), on_webgpu.adapter.device.c_str(),
              on_vulkan.adapter.device.c_str(), d.describe().c_str());
  EXPECT_EQ(d.non_finite, 0u);
  if (compute_only(c) || (on_llvmpipe(on_vulkan.adapter) && on_llvmpipe(on_webgpu.adapter))) {
    EXPECT_EQ(webgpu.rgba, vulkan.rgba) << d.describe();
    return;
  }
  EXPECT_LE(d.relative_mean_error, 1e-5) << d.describe();
  EXPECT_LE(d.outlier_fraction, 0.001) << d.describe();
}

INSTANTIATE_TEST_SUITE_P(Shipped, CrossBackend, ::testing::ValuesIn(shipped_configs()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return config_test_name(info.param); });

}  // namespace
}  // namespace volgraph::testing
