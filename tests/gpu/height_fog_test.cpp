// height_fog (then fog_apply) on both backends, where the answer is known: the background
// through the fog to the far plane, T = e^(−σt·Δ) with Δ the closed-form unit-density length
// (media.h), and with a directional light dimmed by the fog between each point and it
// (τ_sun(y) = σt·e^(−falloff·y)/(falloff·ω_y), as the reference) L_scat = ∫ σs(t)·p_HG·E·
// e^(−τ_view(t) − τ_sun(t)) dt by adaptive Simpson (fp16: 1e-3 relative; composed T + L_scat
// 2e-3); a sun below the horizon adds nothing. Fixture: closed_fog.h.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "physics/light_transmittance.h"
#include "physics/media.h"
#include "physics/phase.h"
#include "tests/gpu/closed_fog.h"
#include "tests/support/adaptive_simpson.h"

namespace volgraph::testing {
namespace {

class HeightFogPass : public ClosedFogFixture {};

TEST_P(HeightFogPass, HeightFogTransmittanceAndDirectionalInScatteringAreExact) {
  ClosedCase c;
  c.technique = "height_fog";
  c.variant = "closed_form";
  c.media = R"({ "height_fog": { "sigma_s": [0.1, 0.2, 0.3], "sigma_a": [0.05, 0.05, 0.05], "g": 0.5, "base_height": 0, "falloff": 0.4 } })";
  c.lights = R"([ { "type": "directional", "direction": [0.3, -0.4, -0.866], "irradiance": [2, 3, 4], "cast_shadows": false } ])";
  c.background = "[1, 1, 1]";
  c.camera = R"({ "position": [0, 1, 0], "target": [0, 0.6, -1], "fov_y_deg": 60, "near": 0.1, "far": 30 })";
  const LoadedConfig config = load(c);
  const Rendered r = render(config);
  const Camera& camera = config.config.scene.camera;
  const double sigma_s[3] = {0.1, 0.2, 0.3}, e[3] = {2, 3, 4};
  const Vec3 travel = physics::normalize({0.3, -0.4, -0.866});
  for (uint32_t j = 0; j < kClosedFogHeight; ++j) {
    for (uint32_t i = 0; i < kClosedFogWidth; ++i) {
      const Vec3 d = closed_fog_pixel_direction(camera, i, j);
      const double length = camera.far * ray_scale(camera, i, j);
      const double unit_depth = physics::height_fog_optical_depth(1.0, 0.4, 0.0, camera.position[1], d[1], length);
      const double phase = physics::phase_hg(0.5, -physics::dot(travel, d));
      for (size_t ch = 0; ch < 3; ++ch) {
        const double sigma_t = sigma_s[ch] + 0.05, t = std::exp(-sigma_t * unit_depth);
        // σs(s)·E·e^(−τ_view(s) − τ_sun(s)) at s metres along the ray, ω_y = 0.4/|direction|.
        const auto integrand = [&](double s) {
          const double y = camera.position[1] + s * d[1];
          const double view = sigma_t * physics::height_fog_optical_depth(1.0, 0.4, 0.0, camera.position[1], d[1], s);
          const double sun = sigma_t * std::exp(-0.4 * y) / (0.4 * -travel[1]);
          return sigma_s[ch] * std::exp(-0.4 * y) * e[ch] * std::exp(-view - sun);
        };
        const double scattering = phase * test::adaptive_simpson(integrand, 0, length, 1e-9, 40);
        // The shader's closed form, by its CPU twins, is that integral.
        const Light& sun = config.config.scene.lights[0];
        const Media& media = config.config.scene.media;
        const Vec3 end = physics::add(camera.position, physics::scaled(d, length));
        const double at_start = physics::fog_optical_depth_to_light(media, sun, camera.position)[ch];
        const double at_end = physics::fog_optical_depth_to_light(media, sun, end)[ch];
        const double closed = sigma_s[ch] * phase * e[ch] *
                              physics::attenuated_length_from(at_start, sigma_t * unit_depth + at_end - at_start, unit_depth);
        EXPECT_NEAR(closed, scattering, 1e-6 * scattering + 1e-9) << "pixel " << i << ", " << j << ": the closed form";
        const std::string where = "pixel " + std::to_string(i) + ", " + std::to_string(j);
        expect_near_relative(r.at(r.transmittance, i, j, ch), t, where + " T");
        expect_near_relative(r.at(r.scattering, i, j, ch), scattering, where + " L_scat");
        expect_near_relative(r.at(r.image, i, j, ch), t + scattering, where + " composed", kComposed);
      }
    }
  }
}

// A sun whose light travels upward reaches the height fog only through infinitely dense fog
// below it (the reference's optical depth to infinity is infinite): no in-scattering.
TEST_P(HeightFogPass, HeightFogGetsNoLightFromASunBelowTheHorizon) {
  ClosedCase c;
  c.technique = "height_fog";
  c.variant = "closed_form";
  c.media = R"({ "height_fog": { "sigma_s": [0.1, 0.2, 0.3], "sigma_a": [0.05, 0.05, 0.05], "g": 0.5, "base_height": 0, "falloff": 0.4 } })";
  c.lights = R"([ { "type": "directional", "direction": [0.3, 0.4, -0.866], "irradiance": [2, 3, 4], "cast_shadows": false } ])";
  const Rendered r = render(load(c));
  for (size_t k = 0; k < r.scattering.rgba.size(); k += 4) {
    for (size_t ch = 0; ch < 3; ++ch) ASSERT_EQ(r.scattering.rgba[k + ch], 0.0f) << "pixel " << k / 4 << " channel " << ch;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, HeightFogPass, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
