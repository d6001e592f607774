// analytic_fog (then fog_apply) on both backends: one point light in global fog, no surfaces,
// against the CPU reference (reference/, tolerance 1e-7): largest relative error per pixel
// ≤ 2e-3 (fp16 storage 5e-4, quadrature 3e-5; measured, printed). Fixture: closed_fog.h.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "reference/image_render.h"
#include "tests/gpu/closed_fog.h"

namespace volgraph::testing {
namespace {

class AnalyticFogPass : public ClosedFogFixture {};

TEST_P(AnalyticFogPass, AnalyticFogMatchesTheCpuReferenceForAPointLight) {
  ClosedCase c;
  c.technique = "analytic_fog";
  c.variant = "airlight";
  c.media = R"({ "fog": { "sigma_s": [0.2, 0.3, 0.4], "sigma_a": [0.05, 0.05, 0.05], "g": 0.3 } })";
  c.lights = R"([ { "type": "point", "position": [0.6, 1.3, -4], "intensity": [5, 5, 5], "cast_shadows": false } ])";
  c.camera = R"({ "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 50, "near": 0.1, "far": 30 })";
  const LoadedConfig config = load(c);
  const Rendered r = render(config);
  reference::IntegrationSettings precise;
  precise.relative_tolerance = 1e-7;
  const reference::Renderer renderer(config.config.scene, precise);
  const reference::ReferenceImage want = reference::render_image(renderer, {.width = kClosedFogWidth, .height = kClosedFogHeight});
  double worst = 0;
  for (uint32_t j = 0; j < kClosedFogHeight; ++j) {
    for (uint32_t i = 0; i < kClosedFogWidth; ++i) {
      const Vec3 expected = want.at(i, j);
      for (size_t ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(r.at(r.image, i, j, ch) - expected[ch]) / expected[ch]);
    }
  }
  std::printf("analytic_fog vs reference: %.3g relative at most\n", worst);
  EXPECT_LT(worst, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(Backends, AnalyticFogPass, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
