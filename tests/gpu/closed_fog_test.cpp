// The closed-form per-pixel fog techniques together (depth_fog, height_fog, analytic_fog,
// each followed by fog_apply) on both backends, stressed: a light exactly on a pixel's ray
// and at the camera, σt 0 (emission only) and 1e4, g ±0.999: no NaN or Inf, transmittance
// in [0, 1]. Each technique's exact answers are in its own file (depth_fog_test.cpp,
// height_fog_test.cpp, analytic_fog_test.cpp); the fixture is closed_fog.h.
#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/gpu/closed_fog.h"

namespace volgraph::testing {
namespace {

class ClosedFog : public ClosedFogFixture {};

TEST_P(ClosedFog, StressLimitsLeaveNoNanOrInf) {
  // Each medium as a global fog and as a height fog (at extreme falloff).
  const char* coefficients[] = {
      R"("sigma_s": [0, 0, 0], "sigma_a": [0, 0, 0], "emission": [0.1, 0.1, 0.1])",
      R"("sigma_s": [1e4, 1e4, 1e4], "sigma_a": [0, 0, 0], "g": 0.999)",
      R"("sigma_s": [0.5, 0.5, 0.5], "sigma_a": [0, 0, 0], "g": -0.999)",
      R"("sigma_s": [0.5, 0.5, 0.5], "sigma_a": [0, 0, 0], "g": 0.999)",
  };
  // Light 0 exactly on pixel (10, 7)'s ray 5 m out, light 1 at the camera.
  const Camera probe{.position = {0, 1, 0}, .target = {0, 1, -1}, .fov_y_deg = 50};
  const Vec3 on_ray = physics::add(probe.position, physics::scaled(closed_fog_pixel_direction(probe, 10, 7), 5));
  std::ostringstream lights;
  lights << R"([ { "type": "point", "position": [)" << on_ray[0] << ", " << on_ray[1] << ", " << on_ray[2]
         << R"(], "intensity": [1e4, 1e4, 1e4], "cast_shadows": false },
                 { "type": "spot", "position": [0, 1, 0], "direction": [0, 0, -1], "intensity": [1e4, 1e4, 1e4], "cast_shadows": false },
                 { "type": "directional", "direction": [0, 0, -1], "irradiance": [10, 10, 10], "cast_shadows": false } ])";
  const struct {
    const char* technique;
    const char* variant;
    const char* params;
  } techniques[] = {{"analytic_fog", "airlight", "{}"}, {"height_fog", "closed_form", "{}"}, {"depth_fog", "exponential", R"({ "density": 1e4 })"}};
  for (const auto& [technique, variant, params] : techniques) {
    for (const char* m : coefficients) {
      ClosedCase c;
      c.technique = technique;
      c.variant = variant;
      c.params = params;
      c.media = std::string(technique) == "height_fog"
                    ? std::string(R"({ "height_fog": { )") + m + R"(, "base_height": -1000, "falloff": 1000 } })"
                    : std::string(R"({ "fog": { )") + m + " } }";
      c.lights = lights.str();
      c.background = "[1, 1, 1]";
      const Rendered r = render(load(c));
      for (const Texels* t : {&r.image, &r.scattering, &r.transmittance}) {
        for (size_t k = 0; k < t->rgba.size(); ++k) ASSERT_TRUE(std::isfinite(t->rgba[k])) << technique << " " << m << " value " << k;
      }
      for (size_t k = 0; k < r.transmittance.rgba.size(); ++k) {
        ASSERT_GE(r.transmittance.rgba[k], 0.0f) << technique << " " << m;
        ASSERT_LE(r.transmittance.rgba[k], 1.0f) << technique << " " << m;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, ClosedFog, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
