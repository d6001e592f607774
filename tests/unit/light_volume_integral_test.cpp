// light_volume's I(t) (physics/light_volume_integral.h) against brute force: a
// 2·10⁶-step midpoint sum in double of raymarch_fog's integrand in a homogeneous medium,
// built from lighting.h (light_arriving: I·cone/d²), phase.h and e^(−σt·(s + d)):
// - spot lights whose cone the ray enters and leaves (both cones crossed), a ray along the
//   axis, a ray that never meets the cone, a point light near the ray, σt 0 … 2 /m,
//   g −0.5 … 0.9: measured 1.4e-6 relative in double (the ray along the axis into the
//   light, where the midpoint sum itself is that far off), 3.1e-6 in float; bounds 3e-6
//   and 1e-4;
// - without the cuts at the cone crossings the same rule is far worse (measured 5.8e-5
//   against 5.5e-14 with them, on a ray across both cones): the cuts make it accurate;
// - directional: the closed form p_HG·(1 − e^(−σt·D))/σt (1e-9: the test's own direct
//   form cancels at σt·D ~ 1e-5);
// - a light on the ray or at the camera, σt 0 and 1e4, g ±0.999: finite, ≥ 0.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/light_volume_integral.h"

namespace volgraph::physics {
namespace {

using V3 = std::array<double, 3>;

Light scene_spot(const V3& position, const V3& direction, double inner, double outer) {
  Light l;
  l.type = LightType::spot;
  l.position = position;
  l.direction = normalize(direction);
  l.intensity = {1, 1, 1};
  l.inner_cone_deg = inner;
  l.outer_cone_deg = outer;
  return l;
}

template <typename Real>
RayLight<Real> ray_light(const Light& l) {
  RayLight<Real> r;
  r.type = l.type == LightType::directional ? kLightTypeDirectional : l.type == LightType::point ? kLightTypePoint : kLightTypeSpot;
  const V3 d = normalize(l.direction);
  for (size_t i = 0; i < 3; ++i) {
    r.position[i] = Real(l.position[i]);
    r.direction[i] = Real(d[i]);
  }
  r.cos_outer = Real(std::cos(l.outer_cone_deg * M_PI / 180));
  r.cos_inner = Real(std::cos(l.inner_cone_deg * M_PI / 180));
  return r;
}

// ∫₀^D p_HG·E·e^(−σt(s + d)) ds by a midpoint sum (per unit intensity).
double midpoint(const Light& light, const V3& origin, const V3& direction, double length, double sigma_t, double g,
                int steps = 2000000) {
  const double ds = length / steps;
  double sum = 0;
  for (int i = 0; i < steps; ++i) {
    const double s = (i + 0.5) * ds;
    const V3 p = add(origin, scaled(direction, s));
    const LightArriving a = light_arriving(light, p);
    const double d = std::sqrt(dot(sub(p, light.position), sub(p, light.position)));
    sum += phase_hg(g, -dot(a.travel, direction)) * a.irradiance[0] * std::exp(-sigma_t * (s + d));
  }
  return sum * ds;
}

struct IntegralCase {
  Light light;
  V3 origin, direction;
  double length, sigma_t, g;
};

std::vector<IntegralCase> cases() {
  const Light down = scene_spot({0, 6, 0}, {0, -1, 0}, 15, 25);
  const Light tilted = scene_spot({-4, 5, 2}, {1, -1, -0.5}, 10, 30);
  Light point = down;
  point.type = LightType::point;
  return {
      {down, {-8, 1, 0}, normalize(V3{1, 0, 0}), 16, 0.1, 0.3},     // across both cones, out again
      {down, {-8, 1, 0}, normalize(V3{1, 0, 0}), 8.5, 0.5, 0.9},    // ends inside the inner cone
      {down, {-8, 1, 0.5}, normalize(V3{1, 0.2, 0}), 20, 0.0, -0.5},  // crossing at a slant
      {down, {0, 0, 0}, normalize(V3{0, 1, 0}), 5.9, 0.2, 0.5},       // along the axis toward the light
      {down, {-8, 7, 0}, normalize(V3{1, 0, 0}), 16, 0.2, 0.0},      // above the light: never lit
      {tilted, {5, 1, 8}, normalize(V3{-0.3, 0.05, -1}), 25, 0.05, 0.7},
      {tilted, {6, 2, -3}, normalize(V3{-1, -0.1, 0.2}), 30, 2.0, 0.2},
      {point, {-8, 5.5, 0}, normalize(V3{1, 0, 0}), 16, 0.3, 0.6},  // 0.5 m under a point light
  };
}

template <typename Real>
Real evaluate(const IntegralCase& c, int panels = kLightVolumePanels) {
  const std::array<Real, 3> o{Real(c.origin[0]), Real(c.origin[1]), Real(c.origin[2])};
  const std::array<Real, 3> d{Real(c.direction[0]), Real(c.direction[1]), Real(c.direction[2])};
  return light_scattering_to(ray_light<Real>(c.light), o, d, Real(c.length), Real(c.sigma_t), Real(c.g), panels);
}

TEST(LightVolumeIntegral, PointAndSpotLightsMatchAMidpointSum) {
  double worst_double = 0, worst_float = 0;
  for (size_t i = 0; const IntegralCase& c : cases()) {
    const double want = midpoint(c.light, c.origin, c.direction, c.length, c.sigma_t, c.g);
    const double got = evaluate<double>(c);
    const double got_float = evaluate<float>(c);
    if (want == 0) {
      EXPECT_EQ(got, 0.0) << "case " << i;
      EXPECT_EQ(got_float, 0.0f) << "case " << i;
      ++i;
      continue;
    }
    worst_double = std::max(worst_double, std::abs(got - want) / want);
    worst_float = std::max(worst_float, std::abs(got_float - want) / want);
    EXPECT_NEAR(got / want, 1.0, 3e-6) << "case " << i;
    EXPECT_NEAR(got_float / want, 1.0, 1e-4) << "case " << i;
    ++i;
  }
  std::printf("light_volume integral vs 2e6-step midpoint: %.3g relative in double, %.3g in float\n", worst_double, worst_float);
}

// The same Gauss–Legendre budget without the cuts at the cone crossings (one piece per
// ray, as many panels as the cut version uses at most) integrates across the cone's kinks.
TEST(LightVolumeIntegral, WithoutTheConeCutsTheRuleIsWorse) {
  const IntegralCase c = cases()[0];
  const double want = midpoint(c.light, c.origin, c.direction, c.length, c.sigma_t, c.g);
  // The spot over [0, D] as one piece, with 5 pieces' worth of panels.
  const RayLight<double> spot = ray_light<double>(c.light);
  const AirlightGeometry<double> geometry = airlight_geometry(c.origin, c.direction, spot.position);
  V3 perpendicular{};
  for (size_t i = 0; i < 3; ++i) perpendicular[i] = spot.position[i] - c.origin[i] - geometry.t_c * c.direction[i];
  const double uncut = point_scattering_piece(spot, geometry, c.direction, perpendicular, 0.0, c.length, c.sigma_t, c.g,
                                              5 * kLightVolumePanels);
  const double cut = evaluate<double>(c);
  std::printf("across the cone: cut %.3g, uncut %.3g relative error\n", std::abs(cut - want) / want, std::abs(uncut - want) / want);
  EXPECT_GT(std::abs(uncut - want), 100 * std::abs(cut - want));
}

TEST(LightVolumeIntegral, DirectionalIsTheClosedForm) {
  Light sun;
  sun.type = LightType::directional;
  sun.direction = normalize(V3{0.3, -1, 0.2});
  const V3 view = normalize(V3{1, 0.1, -1});
  const double cos_theta = -dot(sun.direction, view);
  for (const double sigma_t : {0.0, 1e-6, 0.3, 50.0}) {
    const IntegralCase c{sun, {0, 1, 0}, view, 12, sigma_t, 0.6};
    const double want = phase_hg(0.6, cos_theta) * (sigma_t > 0 ? (1 - std::exp(-sigma_t * 12)) / sigma_t : 12.0);
    EXPECT_NEAR(evaluate<double>(c) / want, 1.0, 1e-9) << sigma_t;
  }
}

TEST(LightVolumeIntegral, StressIsFiniteAndNonNegative) {
  const Light spot = scene_spot({0, 1, 0}, {0, 0, -1}, 20, 30);
  for (const double sigma_t : {0.0, 1e4}) {
    for (const double g : {-0.999, 0.999}) {
      // At the camera, on the ray ahead, and on the ray behind.
      for (const V3& origin : {V3{0, 1, 0}, V3{0, 1, 3}, V3{0, 1, -3}}) {
        const IntegralCase c{spot, origin, normalize(V3{0, 0, -1}), 10, sigma_t, g};
        const float f = evaluate<float>(c);
        const double d = evaluate<double>(c);
        EXPECT_TRUE(std::isfinite(f) && f >= 0) << f;
        EXPECT_TRUE(std::isfinite(d) && d >= 0) << d;
      }
    }
  }
}

}  // namespace
}  // namespace volgraph::physics
