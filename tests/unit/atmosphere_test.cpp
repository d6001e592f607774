// The atmosphere's CPU physics (physics/atmosphere.h): the stable ray–sphere distances
// against the textbook quadratic, the closed-form zenith optical depth against the
// quadrature and by hand, transmittance's monotonicity in the zenith angle, the sun's
// disk smoothing, the presets, and the stress cases (0 m, 1 mm, 10 km, 100 km and 1000 km
// above the ground, the horizon within 1e-6, the sun below it, a planet of 1 km): finite
// everywhere.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/atmosphere.h"
#include "physics/atmosphere_lut.h"
#include "physics/phase.h"

namespace volgraph::physics {
namespace {

const Atmosphere kEarth{};

double relative_error(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

bool finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }
bool in_unit_range(const Vec3& v) {
  for (double x : v)
    if (!(x >= 0 && x <= 1)) return false;
  return true;
}

// The ground distance from altitude h at zenith cosine mu, in long double: the reference.
long double exact_ground_distance(long double radius, long double h, long double mu) {
  const long double r = radius + h, b = r * mu, c = h * (2 * radius + h);
  return -b - std::sqrt(b * b - c);
}

// The textbook quadratic in float, as Bruneton 2017's DistanceToBottomAtmosphereBoundary
// writes it: −r·mu − √(r²(mu² − 1) + R²).
float textbook_ground_distance(float r, float mu, float radius) {
  return -r * mu - std::sqrt(r * r * (mu * mu - 1.0f) + radius * radius);
}

// The other textbook form: c = r² − R², −b − √(b² − c).
float textbook_ground_distance_from_c(float r, float mu, float radius) {
  const float b = r * mu, c = r * r - radius * radius;
  return -b - std::sqrt(b * b - c);
}

TEST(Atmosphere, GroundDistanceFromOneMetreIsStableInFloatAndDouble) {
  const double R = kEarth.bottom_radius;
  const double exact = double(exact_ground_distance(R, 1, -0.1));
  EXPECT_NEAR(exact, 10.0, 1e-3);  // ≈ h / |mu| for a nearly flat ground
  const std::optional<double> in_double = distance_to_sphere(R + 1, -0.1, R);
  const std::optional<float> in_float = distance_to_sphere(float(R) + 1.0f, -0.1f, float(R));
  ASSERT_TRUE(in_double && in_float);
  EXPECT_LT(relative_error(*in_double, exact), 1e-12);
  EXPECT_LT(relative_error(*in_float, exact), 1e-3) << *in_float;
  EXPECT_LT(relative_error(*distance_to_ground(kEarth, R + 1, -0.1), exact), 1e-12);
  // The textbook forms this test would have caught: 11.1875 m and 9.875 m in float.
  const float textbook = textbook_ground_distance(float(R) + 1.0f, -0.1f, float(R));
  const float textbook_from_c = textbook_ground_distance_from_c(float(R) + 1.0f, -0.1f, float(R));
  EXPECT_NEAR(textbook, 11.19f, 0.01f);
  EXPECT_GT(relative_error(textbook, exact), 0.1) << textbook;
  EXPECT_GT(relative_error(textbook_from_c, exact), 0.01) << textbook_from_c;
  RecordProperty("float_stable_m", std::to_string(*in_float));
  RecordProperty("float_textbook_m", std::to_string(textbook));
}

TEST(Atmosphere, SphereDistancesAtExactPoints) {
  const double R = kEarth.bottom_radius, top = kEarth.top_radius;
  EXPECT_DOUBLE_EQ(distance_to_top(kEarth, R, 1), top - R);
  EXPECT_NEAR(distance_to_top(kEarth, R + 5e3, -1), top + R + 5e3, 1e-6);  // through the planet: the ground ignored
  EXPECT_NEAR(*distance_to_ground(kEarth, R + 5e3, -1), 5e3, 1e-9);
  EXPECT_FALSE(distance_to_ground(kEarth, R + 5e3, 0.0).has_value());
  EXPECT_DOUBLE_EQ(*distance_to_ground(kEarth, R, -0.5), 0.0);  // on the ground, heading down
  // Horizontal from the ground: the top at √(top² − R²).
  EXPECT_NEAR(distance_to_top(kEarth, R, 0), std::sqrt(top * top - R * R), 1e-6);
  EXPECT_DOUBLE_EQ(distance_to_boundary(kEarth, R + 5e3, -1), *distance_to_ground(kEarth, R + 5e3, -1));
  EXPECT_DOUBLE_EQ(distance_to_boundary(kEarth, R + 5e3, 0.5), distance_to_top(kEarth, R + 5e3, 0.5));
  // From outside, heading away or missing: no hit.
  EXPECT_FALSE(distance_to_sphere(2 * R, 0.1, R).has_value());
  EXPECT_FALSE(distance_to_sphere(2 * R, -0.5, R).has_value());  // tangent cos is −√3/2: misses
  EXPECT_NEAR(*distance_to_sphere(2 * R, -1.0, R), R, 1e-6);
}

TEST(Atmosphere, RadiusAndMuAlongTheRay) {
  const double R = kEarth.bottom_radius;
  EXPECT_NEAR(radius_at(R, 1, 1e3), R + 1e3, 1e-9);
  EXPECT_NEAR(radius_at(R + 10, -1, 10), R, 1e-9);
  EXPECT_NEAR(radius_at(R, 0, 3e5), std::hypot(R, 3e5), 1e-6);
  EXPECT_NEAR(mu_at(R, 0, 3e5), 3e5 / std::hypot(R, 3e5), 1e-12);
  EXPECT_DOUBLE_EQ(mu_at(R, 1, 5e3), 1.0);
  // 1 m straight up from 1 mm above the ground: 1.001 m up.
  EXPECT_NEAR(radius_at(R + 1e-3, 1, 1) - R, 1.001, 1e-9);
}

// Bruneton 2017's profiles integrated by hand: ∫₀^60km e^(−h/8km) = 8 km (1 − e^(−7.5)),
// the Mie 1.2 km (1 − e^(−50)), the ozone tent 10–25–40 km a triangle of base 30 km and
// height 1 (15 km), from 20 km (density 2/3) its part above (5 km · 5/6 + 7.5 km), from 30 km
// (density 2/3: 10 km · 1/3).
TEST(Atmosphere, ProfileIntegralsByHand) {
  const double top = 60e3;
  EXPECT_NEAR(profile_integral(kEarth.rayleigh_density, 0, top), 8e3 * -std::expm1(-7.5), 1e-9);
  EXPECT_NEAR(profile_integral(kEarth.mie_density, 0, top), 1.2e3 * -std::expm1(-50.0), 1e-9);
  EXPECT_NEAR(profile_integral(kEarth.absorption_density, 0, top), 15e3, 1e-6);
  EXPECT_NEAR(profile_integral(kEarth.absorption_density, 20e3, top), 5e3 * 5 / 6 + 7.5e3, 1e-6);
  EXPECT_NEAR(profile_integral(kEarth.absorption_density, 30e3, top), 10e3 / 3, 1e-6);
  EXPECT_NEAR(profile_integral(kEarth.absorption_density, 0, 10e3), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(profile_density(kEarth.absorption_density, 25e3), 1.0);
  EXPECT_DOUBLE_EQ(profile_density(kEarth.absorption_density, 5e3), 0.0);
  EXPECT_NEAR(profile_density(kEarth.absorption_density, 32.5e3), 0.5, 1e-12);
}

// A profile that clamps at 1: e^(−h/H)·2 is 1 up to H ln 2, then exponential.
TEST(Atmosphere, ProfileIntegralHandlesTheClampAtOne) {
  const double H = 1000;
  const DensityProfile clamped{{}, {0, 2, -1 / H, 0, 0}};
  const double knee = H * std::log(2.0);
  EXPECT_NEAR(profile_integral(clamped, 0, 10e3), knee + 2 * H * (std::exp(-knee / H) - std::exp(-10.0)), 1e-9);
}

TEST(Atmosphere, ZenithTransmittanceIsExpOfTheClosedForm) {
  for (const Atmosphere& atmosphere : {kEarth, *atmosphere_preset("mars")}) {
    const double R = atmosphere.bottom_radius;
    for (double h : {0.0, 1e-3, 1e3, 12e3, 30e3}) {
      const Vec3 closed = zenith_optical_depth(atmosphere, h);
      const Vec3 quadrature = optical_depth(atmosphere, R + h, 1, distance_to_top(atmosphere, R + h, 1));
      const Vec3 transmittance = transmittance_to_boundary(atmosphere, R + h, 1);
      for (int c = 0; c < 3; ++c) {
        EXPECT_LT(relative_error(quadrature[c], closed[c]), 1e-9) << atmosphere.preset << " h " << h << " channel " << c;
        EXPECT_LT(relative_error(transmittance[c], std::exp(-closed[c])), 1e-9);
      }
    }
  }
  // The earth's zenith optical depth from the ground, channel by channel.
  const Vec3 tau = zenith_optical_depth(kEarth, 0);
  const double rayleigh = 8e3 * -std::expm1(-7.5), mie = 1.2e3 * -std::expm1(-50.0), ozone = 15e3;
  for (int c = 0; c < 3; ++c) {
    const double expected = kEarth.rayleigh_scattering[c] * rayleigh + kEarth.mie_extinction[c] * mie + kEarth.absorption_extinction[c] * ozone;
    EXPECT_NEAR(tau[c], expected, 1e-12);
  }
}

// The panels against a fine composite Simpson rule along slant and grazing rays.
TEST(Atmosphere, OpticalDepthMatchesAFineQuadrature) {
  const double R = kEarth.bottom_radius;
  struct Ray { double h, mu; };
  for (Ray ray : {Ray{0, 0}, Ray{0, 0.2}, Ray{1e3, -0.01}, Ray{30e3, mu_horizon(kEarth, R + 30e3) + 1e-4}, Ray{15e3, 0.5}}) {
    const double r = R + ray.h, length = distance_to_boundary(kEarth, r, ray.mu);
    const int n = 400000;
    Vec3 simpson{0, 0, 0};
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      const Vec3 e = extinction_at(kEarth, radius_at(r, ray.mu, length * i / n) - R);
      for (int c = 0; c < 3; ++c) simpson[c] += w * e[c] * length / n / 3;
    }
    const Vec3 panels = optical_depth(kEarth, r, ray.mu, length);
    for (int c = 0; c < 3; ++c) EXPECT_LT(relative_error(panels[c], simpson[c]), 1e-9) << "h " << ray.h << " mu " << ray.mu << " c " << c;
  }
}

TEST(Atmosphere, TransmittanceToSpaceIsMonotonicInTheZenithAngle) {
  for (const Atmosphere& atmosphere : {kEarth, *atmosphere_preset("mars")}) {
    for (double h : {0.0, 1.0, 2e3, 20e3, 50e3}) {
      const double r = atmosphere.bottom_radius + h, mu_h = mu_horizon(atmosphere, r);
      Vec3 previous{1, 1, 1};
      for (int i = 0; i <= 64; ++i) {
        const double mu = 1 - (1 - mu_h) * i / 64.0;
        const Vec3 t = transmittance_to_top(atmosphere, r, mu);
        for (int c = 0; c < 3; ++c) EXPECT_LE(t[c], previous[c] * (1 + 1e-12)) << atmosphere.preset << " h " << h << " mu " << mu;
        previous = t;
      }
    }
  }
}

TEST(Atmosphere, SunTransmittanceSmoothsOverTheSunsDisk) {
  const double R = kEarth.bottom_radius, r = R + 1e3;
  const double mu_h = mu_horizon(kEarth, r), half_width = R / r * kEarth.sun_angular_radius;
  EXPECT_NEAR(sun_visible_fraction(kEarth, r, mu_h), 0.5, 1e-12);
  EXPECT_NEAR(sun_visible_fraction(kEarth, r, mu_h - half_width), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(sun_visible_fraction(kEarth, r, mu_h - 2 * half_width), 0.0);
  EXPECT_NEAR(sun_visible_fraction(kEarth, r, mu_h + half_width), 1.0, 1e-12);
  EXPECT_EQ(sun_transmittance(kEarth, r, -0.5), (Vec3{0, 0, 0}));  // the sun well below the horizon
  const Vec3 high = sun_transmittance(kEarth, r, 0.6), top = transmittance_to_top(kEarth, r, 0.6);
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(high[c], top[c]);
  const Vec3 setting = sun_transmittance(kEarth, r, mu_h), at_horizon = transmittance_to_top(kEarth, r, mu_h);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(setting[c], 0.5 * at_horizon[c], 1e-15);
}

TEST(Atmosphere, EnterAtmosphereFromAbove) {
  const double R = kEarth.bottom_radius, top = kEarth.top_radius;
  EXPECT_DOUBLE_EQ(*enter_atmosphere(kEarth, R + 1e3, 0.3), 0.0);  // inside: starts where it is
  EXPECT_NEAR(*enter_atmosphere(kEarth, top + 1e6, -1), 1e6, 1e-6);
  EXPECT_FALSE(enter_atmosphere(kEarth, top + 1e6, 0.0).has_value());  // looks past the limb
  EXPECT_FALSE(enter_atmosphere(kEarth, top + 1e6, 0.5).has_value());  // looks away
  const double mu = -0.9, d = *enter_atmosphere(kEarth, top + 1e6, mu);
  EXPECT_NEAR(radius_at(top + 1e6, mu, d), top, 1e-6);
}

TEST(Atmosphere, Presets) {
  const Atmosphere earth = *atmosphere_preset("earth");
  EXPECT_EQ(earth.bottom_radius, 6360e3);
  EXPECT_EQ(earth.top_radius, 6420e3);
  EXPECT_EQ(earth.rayleigh_scattering, (Vec3{5.802e-6, 13.558e-6, 33.1e-6}));
  EXPECT_EQ(earth.mie_extinction, (Vec3{4.44e-6, 4.44e-6, 4.44e-6}));
  EXPECT_EQ(earth.sun_angular_radius, 0.004675);
  const Atmosphere mars = *atmosphere_preset("mars");
  EXPECT_EQ(mars.preset, "mars");
  EXPECT_EQ(mars.bottom_radius, 3389.5e3);
  EXPECT_NEAR(profile_density(mars.mie_density, 11.1e3), std::exp(-1.0), 1e-12);
  EXPECT_GT(mars.mie_extinction[0], 10 * mars.rayleigh_scattering[2]);  // dust dominates
  EXPECT_NEAR(zenith_optical_depth(mars, 0)[1], 0.5 * -std::expm1(-80 / 11.1) + mars.rayleigh_scattering[1] * 11.1e3 * -std::expm1(-80 / 11.1), 1e-9);
  EXPECT_FALSE(atmosphere_preset("venus").has_value());
}

TEST(Atmosphere, MiePhaseFollowsTheAtmospheresChoice) {
  Atmosphere atmosphere;
  atmosphere.mie_g = 0.8;
  atmosphere.mie_phase = MiePhase::cornette_shanks;
  EXPECT_DOUBLE_EQ(mie_phase(atmosphere, 0.3), phase_cornette_shanks(0.8, 0.3));
  atmosphere.mie_phase = MiePhase::henyey_greenstein;
  EXPECT_DOUBLE_EQ(mie_phase(atmosphere, 0.3), phase_hg(0.8, 0.3));
}

// Every function at the stress points: a camera at 0 m, 1 mm, 10 km, 100 km and 1000 km
// (moved to the top first when above it), the view within 1e-6 of the horizon, the sun
// below it; the earth, mars and a planet of 1 km radius.
TEST(Atmosphere, NoNanOrInfAtTheStressPoints) {
  Atmosphere tiny;
  tiny.bottom_radius = 1e3;
  tiny.top_radius = 1e3 + 60e3;
  for (const Atmosphere& atmosphere : {kEarth, *atmosphere_preset("mars"), tiny}) {
    for (double h : {0.0, 1e-3, 10e3, 100e3, 1000e3}) {
      const double r0 = atmosphere.bottom_radius + h, mu_h = mu_horizon(atmosphere, r0);
      for (double mu0 : {1.0, 0.5, 1e-6, 0.0, -1e-6, mu_h + 1e-6, mu_h, mu_h - 1e-6, -0.5, -1.0}) {
        SCOPED_TRACE(atmosphere.preset + " r " + std::to_string(atmosphere.bottom_radius) + " h " + std::to_string(h) + " mu " + std::to_string(mu0));
        const std::optional<double> entry = enter_atmosphere(atmosphere, r0, mu0);
        if (!entry) continue;
        ASSERT_TRUE(std::isfinite(*entry));
        const double r = std::min(radius_at(r0, mu0, *entry), atmosphere.top_radius), mu = mu_at(r0, mu0, *entry);
        ASSERT_TRUE(std::isfinite(r) && std::isfinite(mu));
        EXPECT_TRUE(std::isfinite(distance_to_top(atmosphere, r, mu)));
        EXPECT_TRUE(std::isfinite(distance_to_boundary(atmosphere, r, mu)));
        EXPECT_TRUE(in_unit_range(transmittance_to_boundary(atmosphere, r, mu)));
        EXPECT_TRUE(in_unit_range(transmittance_to_top(atmosphere, r, mu)));
        EXPECT_TRUE(finite(optical_depth_to_boundary(atmosphere, r, mu)));
        for (double mu_s : {1.0, 0.0, mu_h, -0.01, -1.0}) EXPECT_TRUE(in_unit_range(sun_transmittance(atmosphere, r, mu_s)));
      }
      EXPECT_TRUE(finite(zenith_optical_depth(atmosphere, std::min(h, atmosphere.top_radius - atmosphere.bottom_radius))));
    }
  }
}

// The horizon has no seam: the transmittance to the top is steep near the horizon but
// continuous — its step across mu_h (±1e-6) is within twice the step of the same width
// just above (below the horizon it holds the horizon's value).
TEST(Atmosphere, NoSeamAtTheHorizon) {
  for (double h : {1e-3, 1.0, 10e3}) {
    const double r = kEarth.bottom_radius + h, mu_h = mu_horizon(kEarth, r);
    auto t = [&](double offset) { return transmittance_to_top(kEarth, r, mu_h + offset * 1e-6); };
    for (int c = 0; c < 3; ++c) {
      const double across = std::abs(t(1)[c] - t(-1)[c]);
      const double neighbours = std::abs(t(3)[c] - t(1)[c]);
      EXPECT_LE(across, 2 * neighbours + 1e-15) << "h " << h << " channel " << c;
      EXPECT_EQ(t(-1)[c], t(0)[c]);
    }
  }
}

// Bruneton 2017's transmittance texture: the zenith is x_mu = 0, the horizon x_mu = 1, the
// ground x_r = 0 and the top x_r = 1, each at its texel centre; (r, mu) → uv → (r, mu)
// round trips, and so does uv → (r, mu) → uv at every texel centre of a 256 × 64 texture.
TEST(AtmosphereLut, TransmittanceParametrisationRoundTrips) {
  const TransmittanceLutSize size;
  const double R = kEarth.bottom_radius, top = kEarth.top_radius;
  EXPECT_NEAR(transmittance_lut_uv(kEarth, R, 1, size).u, 0.5 / 256, 1e-12);
  EXPECT_NEAR(transmittance_lut_uv(kEarth, R, 0, size).u, 1 - 0.5 / 256, 1e-12);
  EXPECT_NEAR(transmittance_lut_uv(kEarth, R, 0.3, size).v, 0.5 / 64, 1e-12);
  EXPECT_NEAR(transmittance_lut_uv(kEarth, top, 0.3, size).v, 1 - 0.5 / 64, 1e-12);
  // At the top every upward ray has d = 0 (x_mu = 0): only mu ≤ 0 is recoverable there.
  for (double h : {0.0, 1e-3, 100.0, 8e3, 59.9e3}) {
    const double r = R + h;
    for (double mu : {1.0, 0.5, 0.01, mu_horizon(kEarth, r) + 1e-6, mu_horizon(kEarth, r)}) {
      const RadiusAndMu back = transmittance_lut_r_mu(kEarth, transmittance_lut_uv(kEarth, r, mu, size), size);
      EXPECT_NEAR(back.r, r, 1e-6) << "h " << h << " mu " << mu;
      EXPECT_NEAR(back.mu, mu, 2e-7) << "h " << h << " mu " << mu;
    }
  }
  const RadiusAndMu at_top = transmittance_lut_r_mu(kEarth, transmittance_lut_uv(kEarth, top, -0.1, size), size);  // the horizon is at −0.136
  EXPECT_NEAR(at_top.r, top, 1e-6);
  EXPECT_NEAR(at_top.mu, -0.1, 1e-9);
  for (int j = 0; j < size.height; ++j) {
    for (int i = 0; i < size.width; ++i) {
      const LutUv uv{(i + 0.5) / size.width, (j + 0.5) / size.height};
      const RadiusAndMu rm = transmittance_lut_r_mu(kEarth, uv, size);
      ASSERT_GE(rm.mu, mu_horizon(kEarth, rm.r) - 1e-9) << i << " " << j;  // never below the horizon
      const LutUv again = transmittance_lut_uv(kEarth, rm.r, rm.mu, size);
      EXPECT_NEAR(again.u, uv.u, 1e-7) << i << " " << j;
      EXPECT_NEAR(again.v, uv.v, 1e-9) << i << " " << j;
    }
  }
}

TEST(AtmosphereLut, MultiscatteringParametrisationRoundTrips) {
  const MultiscatteringLutSize size;
  const double R = kEarth.bottom_radius;
  EXPECT_NEAR(multiscattering_lut_uv(kEarth, R, -1, size).u, 0.5 / 32, 1e-15);
  EXPECT_NEAR(multiscattering_lut_uv(kEarth, R + 60e3, 1, size).v, 1 - 0.5 / 32, 1e-15);
  for (int j = 0; j < size.height; ++j) {
    for (int i = 0; i < size.width; ++i) {
      const RadiusAndMuS p = multiscattering_lut_r_mu_s(kEarth, {(i + 0.5) / 32, (j + 0.5) / 32}, size);
      EXPECT_NEAR(p.mu_s, -1 + 2.0 * i / 31, 1e-12);  // texel i holds x = i / (n − 1)
      EXPECT_NEAR(p.r, R + 60e3 * j / 31, 1e-6);
      const LutUv uv = multiscattering_lut_uv(kEarth, p.r, p.mu_s, size);
      EXPECT_NEAR(uv.u, (i + 0.5) / 32, 1e-12);
      EXPECT_NEAR(uv.v, (j + 0.5) / 32, 1e-12);
    }
  }
}

// Hillaire 2020's sky view: the zenith is v's first texel centre, the horizon v = 1/2 from
// either side, the nadir the last texel centre; toward the sun u's first texel centre; the
// latitude mapping is quadratic about the horizon (half the rows within ~1/4 of the angle
// nearest it); round trips both ways.
TEST(AtmosphereLut, SkyViewParametrisationRoundTrips) {
  const SkyViewLutSize size;
  for (double h : {0.0, 1e-3, 1e3, 30e3, 60e3}) {
    const double r = kEarth.bottom_radius + h, mu_h = mu_horizon(kEarth, r);
    EXPECT_NEAR(sky_view_lut_uv(kEarth, r, {1, 1}, size).v, 0.5 / 108, 1e-12);
    EXPECT_NEAR(sky_view_lut_uv(kEarth, r, {-1, 1}, size).v, 1 - 0.5 / 108, 1e-9);
    EXPECT_NEAR(sky_view_lut_uv(kEarth, r, {mu_h, 1}, size).v, 0.5, 1e-7);  // √ of the rounding in θ − θ_h
    EXPECT_NEAR(sky_view_lut_uv(kEarth, r, {mu_h + 1e-9, 1}, size).v, 0.5, 1e-4);
    EXPECT_NEAR(sky_view_lut_uv(kEarth, r, {0.3, 1}, size).u, 0.5 / 192, 1e-12);
    EXPECT_NEAR(sky_view_lut_uv(kEarth, r, {0.3, -1}, size).u, 1 - 0.5 / 192, 1e-12);
    for (int j = 0; j < size.height; ++j) {
      for (int i = 0; i < size.width; i += 7) {
        const LutUv uv{(i + 0.5) / size.width, (j + 0.5) / size.height};
        const SkyViewDirection d = sky_view_lut_direction(kEarth, r, uv, size);
        const LutUv again = sky_view_lut_uv(kEarth, r, d, size);
        EXPECT_NEAR(again.u, uv.u, 1e-9) << "h " << h << " texel " << i << " " << j;
        EXPECT_NEAR(again.v, uv.v, 1e-7) << "h " << h << " texel " << i << " " << j;
      }
    }
  }
  // Non-linear: the row next to the horizon spans a far smaller angle than the zenith's.
  const double r = kEarth.bottom_radius + 1e3;
  auto theta = [&](int row) { return std::acos(sky_view_lut_direction(kEarth, r, {0.5, (row + 0.5) / 108}, size).mu); };
  EXPECT_LT(theta(53) - theta(52), 0.1 * (theta(1) - theta(0)));
}

}  // namespace
// Thin air (docs/reference.md): the panels resolve a layer's scale height only where its
// exponential is above e^(−80); above that the ray is a few panels. Scale heights 1 mm (the
// loader's floor), 1 m and 100 m, Rayleigh and Mie alike: straight up against the closed
// form, and slant from the ground against the flat slab's H/mu (the curvature adds
// ~H/(R·mu²) relative). Before, 4096 panels a call (3 ms) of 15 m each gave 4.7e-12 for
// 3.6e-7 at mu = 0.05.
TEST(Atmosphere, OpticalDepthOfThinAir) {
  for (double H : {1e-3, 1.0, 100.0}) {
    Atmosphere thin = kEarth;
    thin.rayleigh_density = DensityProfile{{}, {0, 1, -1 / H, 0, 0}};
    thin.mie_density = DensityProfile{{}, {0, 1, -1 / H, 0, 0}};
    thin.absorption_extinction = {0, 0, 0};  // no ozone: the slab's form has none
    const double R = thin.bottom_radius;
    for (double h : {0.0, H, 10 * H, 50 * H}) {
      const Vec3 closed = zenith_optical_depth(thin, (R + h) - R);  // the altitude r stands for (R + h rounds by ~1e-9 m)
      const Vec3 quadrature = optical_depth(thin, R + h, 1, distance_to_top(thin, R + h, 1));
      for (int c = 0; c < 3; ++c) EXPECT_LT(relative_error(quadrature[c], closed[c]), 1e-9) << "H " << H << " h " << h << " c " << c;
    }
    for (double mu : {0.05, 0.3, 1.0}) {
      const Vec3 slant = optical_depth(thin, R, mu, 0.5 * distance_to_top(thin, R, mu));
      for (int c = 0; c < 3; ++c) {
        const double slab = (thin.rayleigh_scattering[c] + thin.mie_extinction[c]) * H / mu;
        EXPECT_LT(relative_error(slant[c], slab), 1e-6 + 4 * H / (R * mu * mu)) << "H " << H << " mu " << mu << " c " << c;
      }
    }
  }
}

}  // namespace volgraph::physics
