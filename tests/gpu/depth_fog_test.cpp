// depth_fog (then fog_apply) on both backends, where the answer is known: an emissive wall
// (radiance 0.5) at view depth 10 m; each pixel's fog factor f of its distance along the ray
// (10·|ray|) per variant, exactly: T = f, L_scat = (1 − f)·colour (fp16: 1e-3 relative), the
// composed pixel f·0.5 + (1 − f)·colour (three fp16 roundings: 2e-3). Fixture: closed_fog.h.
#include <string>

#include <gtest/gtest.h>

#include "physics/media.h"
#include "tests/gpu/closed_fog.h"

namespace volgraph::testing {
namespace {

class DepthFogPass : public ClosedFogFixture {};

TEST_P(DepthFogPass, DepthFogIsItsFormulaOfTheDistanceAlongEachRay) {
  const double colour[3] = {0.2, 0.4, 0.8}, wall = 10;
  struct Variant {
    const char* name;
    const char* params;
    double (*f)(double);
  } variants[] = {
      {"linear", R"({ "start": 5, "end": 20, "color": [0.2, 0.4, 0.8] })", [](double z) { return physics::depth_fog_linear(z, 5.0, 20.0); }},
      {"exponential", R"({ "density": 0.08, "color": [0.2, 0.4, 0.8] })", [](double z) { return physics::depth_fog_exponential(z, 0.08); }},
      {"exponential_squared", R"({ "density": 0.07, "color": [0.2, 0.4, 0.8] })",
       [](double z) { return physics::depth_fog_exponential_squared(z, 0.07); }},
  };
  for (const Variant& v : variants) {
    ClosedCase c;
    c.technique = "depth_fog";
    c.variant = v.name;
    c.params = v.params;
    c.objects = R"([ { "shape": "plane", "size": [200, 1, 200], "material": "glow",
                       "transform": { "translate": [0, 1, -10], "rotate_deg": [90, 0, 0] } } ])";
    const LoadedConfig config = load(c);
    const Rendered r = render(config);
    for (uint32_t j = 0; j < kClosedFogHeight; ++j) {
      for (uint32_t i = 0; i < kClosedFogWidth; ++i) {
        const double f = v.f(wall * ray_scale(config.config.scene.camera, i, j));
        for (size_t ch = 0; ch < 3; ++ch) {
          const std::string where = std::string(v.name) + " pixel " + std::to_string(i) + ", " + std::to_string(j);
          expect_near_relative(r.at(r.transmittance, i, j, ch), f, where + " T");
          expect_near_relative(r.at(r.scattering, i, j, ch), (1 - f) * colour[ch], where + " L_scat");
          expect_near_relative(r.at(r.image, i, j, ch), f * 0.5 + (1 - f) * colour[ch], where + " composed", kComposed);
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, DepthFogPass, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
