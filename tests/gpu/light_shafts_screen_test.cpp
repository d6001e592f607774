// light_shafts_screen (passes/fog/light_shafts_screen.cpp) on both backends, against
// physics/light_shafts.h: with nothing drawn every sample sees the sky, so every pixel is
// exactly Σ weight·decayⁱ × E × exposure × fade (the geometric series, fp16 rounding): the sun
// ahead (fade 1) and half its fade margin past the frame's edge (fade 0.5); the sun behind
// the camera gives exactly 0; a box hiding the sun takes light from the pixels whose steps
// cross it and adds none anywhere; the transmittance is exactly 1.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "physics/light_shafts.h"
#include "tests/gpu/config_output_fixture.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr int kShaftSamples = 64;
constexpr double kShaftWeight = 0.02, kShaftDecay = 0.97, kSunIrradiance = 3;

// A 32 × 18 frame from the origin looking along `target`, the sun travelling along `sun`,
// thin fog; `objects` what the scene draws. Outputs the shafts and their transmittance.
std::string shafts_config(const std::string& target, const std::string& sun, const std::string& objects) {
  return R"({ "output": { "size": [32, 18] },
  "scene": { "camera": { "position": [0, 0, 0], "target": )" + target + R"(, "fov_y_deg": 40 },
    "lights": [ { "type": "directional", "direction": )" + sun + R"(, "irradiance": [3, 3, 3] } ],
    "materials": { "black": { "albedo": [0, 0, 0] } },
    "objects": [ )" + objects + R"( ],
    "media": { "fog": { "albedo": [1, 1, 1], "extinction": [0.01, 0.01, 0.01], "g": 0 } } },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "shafts", "type": "light_shafts_screen", "params": { "samples": 64, "weight": 0.02, "decay": 0.97, "fade_margin": 0.25 },
      "inputs": { "depth": "lit.depth" } } ],
    "outputs": ["shafts.fog_scattering", "shafts.fog_transmittance"] } })";
}

// A box far behind everything else, out of the frame: the scene draws something.
constexpr const char* kNothingInView = R"({ "shape": "box", "material": "black", "size": [1, 1, 1], "transform": { "translate": [0, -500, 500] } })";

class LightShaftsScreen : public ConfigOutputOnEachBackend {};

double open_sky() { return physics::open_sky_shafts(kShaftSamples, kShaftWeight, kShaftDecay) * kSunIrradiance; }

TEST_P(LightShaftsScreen, AnOpenSkyGathersTheGeometricSeries) {
  const Texels t = first_output("shafts.json", shafts_config("[0, 0.2, -1]", "[0, -0.2, 1]", kNothingInView));
  const double want = open_sky();
  ASSERT_GT(want, 0.5);
  for (size_t p = 0; p < t.rgba.size(); p += 4) {
    for (size_t c = 0; c < 3; ++c) ASSERT_NEAR(t.rgba[p + c], want, fp16_steps(want) + 1e-5 * want) << "pixel " << p / 4;
  }
}

TEST_P(LightShaftsScreen, TheSunPastTheEdgeFadesAndBehindTheCameraIsNothing) {
  // The sun 0.125 frame widths right of the frame's edge: half the fade margin.
  const double half_width = std::tan(20.0 * M_PI / 180) * 32.0 / 18.0;  // tan(fov_x / 2)
  const double x = half_width * (1 + 2 * 0.125);                           // u = 1.125
  const std::string sun = "[" + std::to_string(-x) + ", 0, 1]";
  const Texels faded = first_output("shafts.json", shafts_config("[0, 0, -1]", sun, kNothingInView));
  const physics::ScreenSun at = physics::screen_sun(physics::view_rays(scene_.camera, 32.0 / 18.0),
                                                    physics::normalize(Vec3{x, 0, -1}), 0.25);
  ASSERT_NEAR(at.fade, 0.5, 1e-9);
  const double want = open_sky() * at.fade;
  for (size_t p = 0; p < faded.rgba.size(); p += 4) ASSERT_NEAR(faded.rgba[p], want, fp16_steps(want) + 1e-5 * want) << "pixel " << p / 4;
  const Texels behind = first_output("shafts.json", shafts_config("[0, 0, -1]", "[0, 0, -1]", kNothingInView));
  for (size_t p = 0; p < behind.rgba.size(); p += 4) {
    for (size_t c = 0; c < 3; ++c) ASSERT_EQ(behind.rgba[p + c], 0.0f) << "pixel " << p / 4;
  }
}

TEST_P(LightShaftsScreen, AnOccluderTakesLightAndAddsNone) {
  const std::string box = R"({ "shape": "box", "material": "black", "size": [2, 2, 2], "transform": { "translate": [0, 0, -20] } })";
  const Texels t = first_output("shafts.json", shafts_config("[0, 0, -1]", "[0, 0, 1]", box));
  const double open = open_sky();
  double least = open;
  for (size_t p = 0; p < t.rgba.size(); p += 4) {
    ASSERT_LE(t.rgba[p], open + fp16_steps(open)) << "pixel " << p / 4;
    least = std::min(least, double(t.rgba[p]));
  }
  EXPECT_LT(least, 0.5 * open) << "pixels whose steps cross the box toward the sun lose light";
}

TEST_P(LightShaftsScreen, TheTransmittanceIsOne) {
  const LoadedConfig loaded = load_config_text("shafts.json", shafts_config("[0, 0, -1]", "[0, 0, 1]", kNothingInView), registry_);
  Executor executor(device(), loaded.graph, &loaded.config.scene, {});
  executor.run_frame();
  const Texels t = executor.read_output(1);
  for (float v : t.rgba) ASSERT_EQ(v, 1.0f);
}

INSTANTIATE_TEST_SUITE_P(Backends, LightShaftsScreen, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
