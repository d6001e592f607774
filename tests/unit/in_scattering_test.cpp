// The in-scattering sum's CPU twin (physics/in_scattering.h, the twin of
// shaders/include/in_scattering.glsl) against the formula written out here by hand,
// S = σs·(Σ_lights p(θ)·E·V·T_media + L_ambient) + emission, with the textbook phase
// functions (HG's (1 − g²)/(4π(1 + g² − 2g cosθ)^1.5), Schlick's (1 − k²)/(4π(1 − k cosθ)²),
// …), E = I/d² or the directional irradiance, T_media = e^(−σt·d) in homogeneous global
// fog toward a point light and 1 toward a directional light (the fog is in its E), in
// closed form whether or not a march or an opacity shadow map covers the light (those are
// for the local volumes): every phase variant, a point light and a directional light, with
// and without ambient and emission, shadowed or not; 1e-12 relative. And the skips change nothing: σs = 0 with
// the light loop skipped or run, a light with V = 0.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/in_scattering.h"

namespace volgraph::physics {
namespace {

constexpr double kPi = 3.14159265358979323846;

double hg(double g, double c) { return (1 - g * g) / (4 * kPi * std::pow(1 + g * g - 2 * g * c, 1.5)); }

// The phase functions by their textbook forms.
double textbook_phase(int code, double g, double cos_theta, double g_back, double w_forward) {
  switch (code) {
    case PHASE_ISOTROPIC: return 1 / (4 * kPi);
    case PHASE_RAYLEIGH: return 3 / (16 * kPi) * (1 + cos_theta * cos_theta);
    case PHASE_SCHLICK: {
      const double k = 1.55 * g - 0.55 * g * g * g;
      return (1 - k * k) / (4 * kPi * (1 - k * cos_theta) * (1 - k * cos_theta));
    }
    case PHASE_DUAL_HG: return w_forward * hg(g, cos_theta) + (1 - w_forward) * hg(g_back, cos_theta);
    default: return hg(g, cos_theta);
  }
}

Light point_light() {
  Light l;
  l.type = LightType::point;
  l.position = {1.5, 3.0, -2.0};
  l.intensity = {20, 15, 10};
  return l;
}

Light directional_light() {
  Light l;
  l.type = LightType::directional;
  l.direction = normalize(Vec3{0.3, -1.0, 0.2});
  l.irradiance = {3, 2.5, 2};
  return l;
}

Media homogeneous_fog() {
  Media m;
  m.fog = Medium{.sigma_s = {0.05, 0.06, 0.07}, .sigma_a = {0.02, 0.01, 0.03}, .g = 0.4};
  return m;
}

const int kCodes[] = {PHASE_HG, PHASE_ISOTROPIC, PHASE_RAYLEIGH, PHASE_SCHLICK, PHASE_DUAL_HG};

// A shadow map over light 0 that lets `v` (per channel) through and, when `mapped`, holds
// the local volumes' transmittance toward it (no march).
struct MapOnLightZero {
  Vec3 v{1, 1, 1};
  bool mapped = false;
  Vec3 visibility(size_t light, const Vec3&) const { return light == 0 ? v : Vec3{1, 1, 1}; }
  bool media_shadow_mapped(size_t light) const { return mapped && light == 0; }
};

// S by hand at p toward the camera, for the lights (each with its V).
struct HandLight {
  Light light;
  Vec3 visibility{1, 1, 1};
};
Vec3 by_hand(const MediaSample& m, const Vec3& p, const Vec3& to_camera, const PhaseChoice& phase, const std::vector<HandLight>& lights,
             const Vec3& ambient, const Media& media) {
  const Vec3 sigma_t = media.fog ? add(media.fog->sigma_s, media.fog->sigma_a) : Vec3{0, 0, 0};
  Vec3 sum = ambient;
  for (const HandLight& h : lights) {
    Vec3 e, travel;
    double distance = 0;
    if (h.light.type == LightType::directional) {
      e = h.light.irradiance;
      travel = h.light.direction;
    } else {
      const Vec3 d = sub(p, h.light.position);
      distance = std::sqrt(dot(d, d));
      e = scaled(h.light.intensity, 1 / (distance * distance));
      travel = scaled(d, 1 / distance);
    }
    const double p_theta = textbook_phase(phase.code, m.g, dot(travel, to_camera), phase.g_back, phase.w_forward);
    for (size_t c = 0; c < 3; ++c) {
      // Directional lights: the global fog is in E (T = 1); point lights: e^(−σt·d).
      const double t = h.light.type != LightType::directional ? std::exp(-sigma_t[c] * distance) : 1.0;
      sum[c] += p_theta * e[c] * h.visibility[c] * t;
    }
  }
  Vec3 s;
  for (size_t c = 0; c < 3; ++c) s[c] = m.sigma_s[c] * sum[c] + m.emission[c];
  return s;
}

void expect_near(const Vec3& got, const Vec3& want, const std::string& what) {
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-12 * std::abs(want[c]) + 1e-300) << what << " channel " << c;
}

TEST(InScattering, MatchesTheFormulaForEveryPhaseVariantLightAmbientAndEmission) {
  const Media media = homogeneous_fog();
  const Vec3 p{-0.5, 1.2, -4.0};
  const Vec3 to_camera = normalize(sub(Vec3{0, 1, 0}, p));
  const LightMarch march{.steps = 3, .max_distance = 50, .jitter = 0.5};  // exact in homogeneous fog
  size_t checked = 0;
  for (int code : kCodes) {
    for (double g : {-0.6, 0.0, 0.4, 0.9}) {
      const PhaseChoice phase{code, -0.35, 0.65};
      for (const Vec3& ambient : {Vec3{0, 0, 0}, Vec3{0.1, 0.2, 0.3}}) {
        for (const Vec3& emission : {Vec3{0, 0, 0}, Vec3{0.01, 0.02, 0.005}}) {
          const MediaSample m{.sigma_s = media.fog->sigma_s, .sigma_a = media.fog->sigma_a, .emission = emission, .g = g};
          for (const Light& light : {point_light(), directional_light()}) {
            const std::vector<Light> lights = {light};
            const std::string what = "phase " + std::to_string(code) + " g " + std::to_string(g) + (light.type == LightType::point ? " point" : " directional") +
                                     " ambient " + std::to_string(ambient[0]) + " emission " + std::to_string(emission[0]);
            expect_near(in_scattering(m, p, to_camera, phase, lights, ambient, media, march, true),
                        by_hand(m, p, to_camera, phase, {{light}}, ambient, media), what);
            ++checked;
          }
          // Both lights at once, the point light behind a shadow map letting (0.5, 0.25, 0)
          // through that also holds its volumes' transmittance (so no march for it; the fog
          // still dims it in closed form).
          const std::vector<Light> both = {point_light(), directional_light()};
          const MapOnLightZero map{{0.5, 0.25, 0}, true};
          expect_near(in_scattering(m, p, to_camera, phase, both, ambient, media, march, true, map),
                      by_hand(m, p, to_camera, phase, {{both[0], map.v}, {both[1]}}, ambient, media), "two lights, shadow-mapped");
        }
      }
    }
  }
  EXPECT_EQ(checked, 5u * 4 * 2 * 2 * 2);
}

// The global fog dims the light in closed form without any march (steps 0, the default).
TEST(InScattering, WithoutAMarchTheFogStillDimsTheLight) {
  const Media media = homogeneous_fog();
  const Vec3 p{0.5, 0.8, -3.0}, to_camera = normalize(sub(Vec3{0, 1, 0}, p));
  const MediaSample m{.sigma_s = media.fog->sigma_s, .emission = {0, 0, 0}, .g = 0.3};
  const PhaseChoice phase{PHASE_HG};
  expect_near(in_scattering(m, p, to_camera, phase, {point_light()}, {0, 0, 0}, media, LightMarch{.steps = 0}, true),
              by_hand(m, p, to_camera, phase, {{point_light()}}, {0, 0, 0}, media), "steps 0");
}

// g beyond ±0.998 is clamped there for every variant that reads it (HG's peak would
// overflow rgba16f), as in phase.glsl's callers.
TEST(InScattering, ThePhaseClampsGWhereHgsPeakWouldOverflowFp16) {
  for (int code : kCodes) {
    const PhaseChoice phase{code, -0.3, 0.7};
    EXPECT_EQ(phase_of(phase, 0.9999, 0.99), phase_of(phase, 0.998, 0.99)) << code;
    EXPECT_EQ(phase_of(phase, -1.0, -0.99), phase_of(phase, -0.998, -0.99)) << code;
    EXPECT_NEAR(phase_of(phase, 0.5, 0.2), textbook_phase(code, 0.5, 0.2, -0.3, 0.7), 1e-14) << code;
  }
}

// The early exit: where σs is zero in every channel the light loop is skipped and S is the
// emission — the same value as running it (σs·(…) = 0); a light that delivers nothing
// (V = 0) adds nothing, marched or not.
TEST(InScattering, TheSkipsChangeNothing) {
  const Media media = homogeneous_fog();
  const Vec3 p{0.2, 1.5, -5.0}, to_camera = normalize(sub(Vec3{0, 1, 0}, p));
  const std::vector<Light> lights = {point_light(), directional_light()};
  const LightMarch march{.steps = 4};
  for (int code : kCodes) {
    const PhaseChoice phase{code};
    const MediaSample empty{.emission = {0.1, 0.2, 0.3}, .g = 0.5};
    const Vec3 skipped = in_scattering(empty, p, to_camera, phase, lights, {0.4, 0.4, 0.4}, media, march, true);
    const Vec3 run = in_scattering(empty, p, to_camera, phase, lights, {0.4, 0.4, 0.4}, media, march, false);
    EXPECT_EQ(skipped, empty.emission);
    EXPECT_EQ(run, empty.emission);
    const MediaSample m{.sigma_s = {0.1, 0.1, 0.1}, .g = 0.5};
    const Vec3 dark = in_scattering(m, p, to_camera, phase, lights, {0, 0, 0}, media, march, true, MapOnLightZero{{0, 0, 0}});
    const Vec3 without = in_scattering(m, p, to_camera, phase, {lights[1]}, {0, 0, 0}, media, march, true);
    EXPECT_EQ(dark, without) << "a fully shadowed light adds nothing";
  }
}

}  // namespace
}  // namespace volgraph::physics
