// The closed-form per-pixel fog techniques (depth_fog, height_fog, analytic_fog, each
// followed by fog_apply) on both backends, where the answer is known:
// - depth_fog: an emissive wall (radiance 0.5) at view depth 10 m; each pixel's fog
//   factor f of its distance along the ray (10·|ray|) per variant, exactly: T = f,
//   L_scat = (1 − f)·colour (fp16: 1e-3 relative), the composed pixel f·0.5 + (1 − f)·colour
//   (three fp16 roundings: 2e-3);
// - height_fog: the background through the fog to the far plane, T = e^(−σt·Δ) with Δ the
//   closed-form unit-density length (media.h), and with a directional light dimmed by the
//   fog between each point and it (τ_sun(y) = σt·e^(−falloff·y)/(falloff·ω_y), as the
//   reference) L_scat = ∫ σs(t)·p_HG·E·e^(−τ_view(t) − τ_sun(t)) dt by adaptive Simpson
//   (fp16: 1e-3 relative; composed T + L_scat 2e-3); a sun below the horizon adds nothing;
// - analytic_fog: one point light in global fog, no surfaces, against the CPU reference
//   (reference/, tolerance 1e-7): largest relative error per pixel ≤ 2e-3 (fp16 storage
//   5e-4, quadrature 3e-5; measured, printed);
// - stress: a light exactly on a pixel's ray and at the camera, σt 0 (emission only) and
//   1e4, g ±0.999: no NaN or Inf, transmittance in [0, 1].
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/camera.h"
#include "physics/light_transmittance.h"
#include "physics/media.h"
#include "physics/phase.h"
#include "reference/image_render.h"
#include "tests/gpu/backends.h"
#include "tests/support/adaptive_simpson.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kClosedFogWidth = 48, kClosedFogHeight = 32;
constexpr double kFp16 = 1e-3;     // one fp16 rounding (4.9e-4) and the float maths
constexpr double kComposed = 2e-3;  // T, L_scat and the colour each rounded to fp16, then blended

struct ClosedCase {
  std::string technique = "depth_fog";
  std::string variant = "exponential";
  std::string params = "{}";
  std::string media = R"({ "fog": { "sigma_s": [0.1, 0.1, 0.1], "sigma_a": [0, 0, 0] } })";
  std::string lights = "[]";
  std::string objects = "[]";
  std::string background = "[0, 0, 0]";
  std::string camera = R"({ "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 50, "near": 0.1, "far": 40 })";
};

// Outputs: 0 the composed linear image, 1 fog_scattering, 2 fog_transmittance.
std::string config_text(const ClosedCase& c) {
  std::ostringstream o;
  o << R"({ "output": { "size": [)" << kClosedFogWidth << ", " << kClosedFogHeight << R"(] },
  "scene": { "camera": )" << c.camera << R"(, "background": { "radiance": )" << c.background << R"( },
             "materials": { "glow": { "albedo": [0, 0, 0], "emissive": [0.5, 0.5, 0.5] } },
             "objects": )" << c.objects << R"(, "lights": )" << c.lights << R"(, "media": )" << c.media << R"( },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "fog", "type": ")" << c.technique << R"(", "variant": ")" << c.variant << R"(", "params": )" << c.params << R"(,
      "inputs": { "depth": "lit.depth" } },
    { "name": "fogged", "type": "fog_apply",
      "inputs": { "color": "lit.color", "fog_scattering": "fog.fog_scattering", "fog_transmittance": "fog.fog_transmittance" } },
    { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "fogged.color" } } ],
    "outputs": ["out.output", "fog.fog_scattering", "fog.fog_transmittance"] } })";
  return o.str();
}

struct Rendered {
  Texels image, scattering, transmittance;
  double at(const Texels& t, uint32_t i, uint32_t j, size_t ch) const { return t.rgba[4 * (j * t.width + i) + ch]; }
};

class ClosedFog : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const ClosedCase& c) { return load_config_text("closed_fog.json", config_text(c), registry_); }
  Rendered render(const LoadedConfig& c) {
    Executor executor(device(), c.graph, &c.config.scene, {});
    executor.run_frame();
    return {executor.read_output(0), executor.read_output(1), executor.read_output(2)};
  }
  PassRegistry registry_;
};

// The length of pixel (i, j)'s ray per metre of view depth.
double ray_scale(const Camera& camera, uint32_t i, uint32_t j) {
  const physics::ViewRays rays = physics::view_rays(camera, double(kClosedFogWidth) / kClosedFogHeight);
  const Vec3 r = physics::view_ray(rays, (i + 0.5) / kClosedFogWidth * 2 - 1, 1 - (j + 0.5) / kClosedFogHeight * 2);
  return std::sqrt(physics::dot(r, r));
}

Vec3 closed_fog_pixel_direction(const Camera& camera, uint32_t i, uint32_t j) {
  const physics::ViewRays rays = physics::view_rays(camera, double(kClosedFogWidth) / kClosedFogHeight);
  return physics::normalize(physics::view_ray(rays, (i + 0.5) / kClosedFogWidth * 2 - 1, 1 - (j + 0.5) / kClosedFogHeight * 2));
}

void expect_near_relative(double got, double want, const std::string& what, double relative = kFp16) {
  EXPECT_NEAR(got, want, relative * std::abs(want) + 1e-6) << what;
}

TEST_P(ClosedFog, DepthFogIsItsFormulaOfTheDistanceAlongEachRay) {
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

TEST_P(ClosedFog, HeightFogTransmittanceAndDirectionalInScatteringAreExact) {
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
TEST_P(ClosedFog, HeightFogGetsNoLightFromASunBelowTheHorizon) {
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

TEST_P(ClosedFog, AnalyticFogMatchesTheCpuReferenceForAPointLight) {
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
