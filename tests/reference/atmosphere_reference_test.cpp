// The atmosphere's CPU reference against closed forms and brute force: with scattering
// off the sky is black and the sun's disk is its radiance times the transmittance; the
// zenith transmittance from the ground is e^(−τ) of physics' closed form; the sky is
// mirror-symmetric about the sun's vertical plane; single scattering against a 10⁵-step
// midpoint sum; the orders' count, residual and decrease for the earth at noon and at
// sunset; aerial perspective against the sky; finite, non-negative values at the horizon
// from 0 m to 1000 km, the sun below the horizon, on the earth and a 1 km planet.
#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/atmosphere.h"
#include "physics/camera.h"
#include "physics/phase.h"
#include "reference/atmosphere_reference.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::dot;
using physics::normalize;
using physics::scaled;

constexpr double kPi = 3.14159265358979323846;

Atmosphere earth() { return *physics::atmosphere_preset("earth"); }

// The sun at elevation `elevation_deg` above the horizon of the point (0, r, 0), toward +X.
AtmosphereSun sun_at(double elevation_deg) {
  const double e = elevation_deg * kPi / 180;
  return {{std::cos(e), std::sin(e), 0}, {1.5, 1.5, 1.5}, 0.004675};
}

// A direction at elevation `elevation_deg` and azimuth `azimuth_deg` from +X toward +Z.
Vec3 direction_at(double elevation_deg, double azimuth_deg) {
  const double e = elevation_deg * kPi / 180, a = azimuth_deg * kPi / 180;
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

AtmosphereReferenceSettings few_samples(uint32_t samples) {
  AtmosphereReferenceSettings s;
  s.samples = samples;
  return s;
}

bool finite_non_negative(const Vec3& v) {
  for (double c : v)
    if (!std::isfinite(c) || c < 0) return false;
  return true;
}

double largest(const Vec3& v) { return std::max({v[0], v[1], v[2]}); }

double elapsed_seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(AtmosphereReference, ScatteringOffTheSkyIsBlackAndTheSunIsItsRadianceTimesTheTransmittance) {
  Atmosphere a = earth();
  a.rayleigh_scattering = {0, 0, 0};
  a.mie_scattering = {0, 0, 0};  // Mie extinction stays: pure absorption
  const AtmosphereSun sun = sun_at(20);
  const AtmosphereReference reference(a, sun, few_samples(8));
  const Vec3 eye{0, a.bottom_radius + 2, 0};
  for (double elevation : {1.0, 10.0, 45.0, 90.0})
    for (double azimuth : {0.0, 90.0, 180.0}) {
      const SkySample s = reference.sky(eye, direction_at(elevation, azimuth), 7);
      EXPECT_EQ(s.radiance, (Vec3{0, 0, 0})) << elevation << " " << azimuth;
    }
  const SkySample at_sun = reference.sky(eye, sun.direction, 7);
  const double r = a.bottom_radius + 2, mu = dot(eye, sun.direction) / r;
  const Vec3 t = physics::transmittance_to_boundary(a, r, mu);
  const double sin_alpha = std::sin(sun.angular_radius);
  for (int c = 0; c < 3; ++c) {
    const double expected = sun.irradiance[c] / (kPi * sin_alpha * sin_alpha) * t[c];
    EXPECT_NEAR(at_sun.radiance[c], expected, 1e-12 * expected) << c;
    EXPECT_LT(t[c], 1.0);
  }
}

TEST(AtmosphereReference, ZenithTransmittanceFromTheGroundIsTheClosedForm) {
  const Atmosphere a = earth();
  const AtmosphereReference reference(a, sun_at(90));
  const Vec3 closed = physics::zenith_optical_depth(a, 0);
  const Vec3 t = reference.transmittance(a.bottom_radius, 1);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], std::exp(-closed[c]), 1e-7 * std::exp(-closed[c])) << c;
}

// Mirroring the view's azimuth about the sun's vertical plane (z → −z) leaves single
// scattering equal to the quadrature's tolerance (1e-6 relative); the Monte Carlo orders
// draw other paths, so the full sky agrees within 4 standard errors.
TEST(AtmosphereReference, SkyIsSymmetricAboutTheSunsVerticalPlane) {
  const Atmosphere a = earth();
  const AtmosphereReference reference(a, sun_at(15), few_samples(32));
  const Vec3 eye{0, a.bottom_radius + 100, 0};
  for (double elevation : {2.0, 30.0})
    for (double azimuth : {40.0, 130.0}) {
      const Vec3 v = direction_at(elevation, azimuth), mirrored{v[0], v[1], -v[2]};
      const Vec3 length_of_ray{physics::distance_to_boundary(a, eye[1], v[1]), 0, 0};
      const Vec3 s1 = reference.single_scattering(eye, v, length_of_ray[0]);
      const Vec3 s2 = reference.single_scattering(eye, mirrored, length_of_ray[0]);
      const SkySample k1 = reference.sky(eye, v, 1), k2 = reference.sky(eye, mirrored, 2);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(s1[c], s2[c], 1e-6 * s1[c]) << elevation << " " << azimuth << " " << c;
        double variance = 0;
        for (size_t k = 0; k < k1.scattering.standard_error.size(); ++k)
          variance += std::pow(k1.scattering.standard_error[k][c], 2) + std::pow(k2.scattering.standard_error[k][c], 2);
        EXPECT_NEAR(k1.radiance[c], k2.radiance[c], 4 * std::sqrt(variance) + 1e-6 * k1.radiance[c])
            << elevation << " " << azimuth << " " << c;
      }
    }
}

// ∫ T J by a 10⁵-step midpoint sum, its optical depth accumulated by half steps and J
// from physics directly.
Vec3 fixed_step_single_scattering(const Atmosphere& a, const AtmosphereSun& sun, const Vec3& eye, const Vec3& v) {
  const double r = std::sqrt(dot(eye, eye)), mu = dot(eye, v) / r;
  const double length = physics::distance_to_boundary(a, r, mu);
  constexpr int kSteps = 100000;
  const double h = length / kSteps;
  const auto altitude = [&](double t) {
    const Vec3 x = add(eye, scaled(v, t));
    return std::max(0.0, std::sqrt(dot(x, x)) - a.bottom_radius);
  };
  Vec3 tau{0, 0, 0}, sum{0, 0, 0};
  const double nu = dot(v, sun.direction);
  for (int i = 0; i < kSteps; ++i) {
    const double t0 = i * h, tm = t0 + 0.5 * h;
    tau = add(tau, scaled(physics::extinction_at(a, altitude(t0 + 0.25 * h)), 0.5 * h));
    const Vec3 x = add(eye, scaled(v, tm));
    const double rx = std::sqrt(dot(x, x));
    const Vec3 t_sun = physics::sun_transmittance(a, std::max(rx, a.bottom_radius), dot(x, sun.direction) / rx);
    const Vec3 sr = physics::rayleigh_scattering_at(a, altitude(tm)), sm = physics::mie_scattering_at(a, altitude(tm));
    for (int c = 0; c < 3; ++c) {
      const double sigma = sr[c] * physics::phase_rayleigh(nu) + sm[c] * physics::mie_phase(a, nu);
      const double j = sigma * sun.irradiance[c] * t_sun[c];
      sum[c] += std::exp(-tau[c]) * j * h;
    }
    tau = add(tau, scaled(physics::extinction_at(a, altitude(t0 + 0.75 * h)), 0.5 * h));
  }
  return sum;
}

// The adaptive quadrature's tolerance is 1e-6 of the integral; the midpoint sum's error
// at 10⁵ steps is below 1e-6 too for these rays (h ≤ 9 m against scale heights of
// 1.2 km): they agree within 5e-6.
TEST(AtmosphereReference, SingleScatteringMatchesAFixedStepSum) {
  const Atmosphere a = earth();
  const auto start = std::chrono::steady_clock::now();
  // Noon's zenith and sunset's low ray away from the sun (the longest path, 5° up).
  const std::pair<double, Vec3> cases[] = {{60.0, direction_at(90, 0)}, {2.0, direction_at(5, 150)}};
  for (const auto& [sun_elevation, v] : cases) {
    const AtmosphereSun sun = sun_at(sun_elevation);
    const AtmosphereReference reference(a, sun);
    const Vec3 eye{0, a.bottom_radius + 10, 0};
    const Vec3 adaptive = reference.single_scattering(eye, v, physics::distance_to_boundary(a, eye[1], v[1]));
    const Vec3 fixed = fixed_step_single_scattering(a, sun, eye, v);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(adaptive[c], fixed[c], 5e-6 * fixed[c]) << sun_elevation << " " << c;
  }
  std::printf("single scattering against the 1e5-step sum: 2 rays in %.2f s\n", elapsed_seconds_since(start));
}

TEST(AtmosphereReference, SingleScatteringByZenithCosinesEqualsTheRaysIntegral) {
  const Atmosphere a = earth();
  const AtmosphereSun sun = sun_at(30);
  const AtmosphereReference reference(a, sun);
  const Vec3 eye{0, a.bottom_radius + 500, 0}, v = direction_at(20, 60);
  const Vec3 by_ray = reference.single_scattering(eye, v, physics::distance_to_boundary(a, eye[1], v[1]));
  const Vec3 by_cosines = reference.single_scattering(eye[1], v[1], sun.direction[1], dot(v, sun.direction));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(by_ray[c], by_cosines[c], 1e-9 * by_ray[c]) << c;
}

// Orders for the earth preset, a camera 10 m above the ground, over 12 view directions
// (below the horizon to 60°, toward, across and away from the sun), 256 paths a ray:
// the number of orders N to reach the threshold (1e-3), the residual beyond N (below
// 5e-3 of the sky), and each order's energy (summed over the directions) below the one
// before, for every order whose sum is above 3 standard errors (at least orders 2-4).
void check_orders(double sun_elevation, const char* name) {
  const Atmosphere a = earth();
  const AtmosphereReference reference(a, sun_at(sun_elevation), few_samples(256));
  const Vec3 eye{0, a.bottom_radius + 10, 0};
  const auto start = std::chrono::steady_clock::now();
  uint32_t max_orders = 0;
  double max_residual = 0;
  const size_t orders = reference.settings().max_orders;
  std::vector<Vec3> energy(orders, Vec3{0, 0, 0}), variance(orders, Vec3{0, 0, 0});
  for (double elevation : {-10.0, 3.0, 20.0, 60.0})
    for (double azimuth : {0.0, 90.0, 180.0}) {
      const SkySample s = reference.sky(eye, direction_at(elevation, azimuth), uint64_t(elevation * 1000 + azimuth));
      ASSERT_TRUE(finite_non_negative(s.radiance));
      max_orders = std::max(max_orders, s.scattering.orders);
      max_residual = std::max(max_residual, largest(s.scattering.residual) / largest(s.scattering.total));
      for (size_t k = 0; k < orders; ++k)
        for (int c = 0; c < 3; ++c) {
          energy[k][c] += s.scattering.radiance[k][c];
          variance[k][c] += std::pow(s.scattering.standard_error[k][c], 2);
        }
    }
  std::printf("%s: orders N = %u at most, residual beyond N at most %.2e of the sky; orders 1-8 (green):", name,
              max_orders, max_residual);
  for (size_t k = 0; k < 8; ++k) std::printf(" %.3e", energy[k][1]);
  std::printf("; 12 rays in %.2f s\n", elapsed_seconds_since(start));
  EXPECT_GE(max_orders, 3u);
  EXPECT_LT(max_orders, reference.settings().max_orders);
  EXPECT_LT(max_residual, 5e-3);
  size_t checked = 0;
  for (size_t k = 1; k < orders; ++k) {
    bool significant = true;
    for (int c = 0; c < 3; ++c) significant = significant && energy[k][c] > 3 * std::sqrt(variance[k][c]);
    if (!significant) break;
    std::printf("  order %zu: %.3e +- %.1e (green)\n", k + 1, energy[k][1], std::sqrt(variance[k][1]));
    ++checked;
    for (int c = 0; c < 3; ++c)
      EXPECT_LT(energy[k][c], energy[k - 1][c]) << name << " order " << k + 1 << " channel " << c;
  }
  std::printf("%s: orders 2-%zu checked\n", name, checked + 1);
  EXPECT_GE(checked, 3u);
}

TEST(AtmosphereReference, OrdersConvergeAndDecreaseAtNoon) { check_orders(60, "noon (sun at 60 deg)"); }
TEST(AtmosphereReference, OrdersConvergeAndDecreaseAtSunset) { check_orders(2, "sunset (sun at 2 deg)"); }

TEST(AtmosphereReference, AerialPerspectiveToTheBoundaryIsTheSkyAndStartsAtNothing) {
  const Atmosphere a = earth();
  const AtmosphereReference reference(a, sun_at(30), few_samples(8));
  const Vec3 eye{0, a.bottom_radius + 50, 0}, v = direction_at(10, 45);
  const SkySample sky = reference.sky(eye, v, 3);
  const AerialPerspectiveSample far = reference.aerial_perspective(eye, v, 1e9, 3);
  EXPECT_EQ(far.in_scattered, sky.scattering.total);
  EXPECT_EQ(far.transmittance, sky.transmittance);
  const AerialPerspectiveSample none = reference.aerial_perspective(eye, v, 0, 3);
  EXPECT_EQ(none.in_scattered, (Vec3{0, 0, 0}));
  EXPECT_EQ(none.transmittance, (Vec3{1, 1, 1}));
  const AerialPerspectiveSample near = reference.aerial_perspective(eye, v, 20e3, 3);
  const Vec3 tau = physics::optical_depth(a, eye[1], v[1], 20e3);
  for (int c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(near.transmittance[c], std::exp(-tau[c]));
    EXPECT_GT(near.in_scattered[c], 0);
    EXPECT_LT(near.in_scattered[c], far.in_scattered[c]);
  }
}

// The paths' first vertices estimate order 1 too (their next-event estimation, the
// distance drawn from the tabulated optical depth, the channels' MIS weights): within 4
// standard errors of the quadrature (plus 1e-6 of it), on the sky, the ground, at noon
// and at sunset, from the ground and from space.
TEST(AtmosphereReference, PathsEstimateOfOrderOneMatchesTheQuadrature) {
  const Atmosphere a = earth();
  int checked = 0;
  for (double sun_elevation : {60.0, 2.0}) {
    const AtmosphereReference reference(a, sun_at(sun_elevation), few_samples(512));
    for (double altitude : {10.0, 300e3})
      for (double elevation : {-30.0, 5.0, 45.0}) {
        const Vec3 eye{0, a.bottom_radius + altitude, 0};
        const Vec3 v = altitude > 100e3 ? direction_at(elevation - 40, 100) : direction_at(elevation, 100);
        const ScatteringOrders s = reference.sky(eye, v, 11).scattering;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(s.order_one_estimate[c], s.radiance[0][c], 4 * s.order_one_error[c] + 1e-6 * s.radiance[0][c])
              << sun_elevation << " " << altitude << " " << elevation << " " << c;
        ++checked;
      }
  }
  EXPECT_EQ(checked, 12);
}

// Gauss–Legendre nodes and weights on [a, b] (n = 4, 6 or 8).
std::vector<std::pair<double, double>> gauss_legendre(double a, double b, int n) {
  static const std::vector<std::pair<double, double>> g4{{-0.8611363115940526, 0.3478548451374538},
                                                         {-0.3399810435848563, 0.6521451548625461}};
  static const std::vector<std::pair<double, double>> g6{{-0.9324695142031521, 0.1713244923791704},
                                                         {-0.6612093864662645, 0.3607615730481386},
                                                         {-0.2386191860831969, 0.4679139345726910}};
  static const std::vector<std::pair<double, double>> g8{{-0.9602898564975363, 0.1012285362903763},
                                                         {-0.7966664774136267, 0.2223810344533745},
                                                         {-0.5255324099163290, 0.3137066458778873},
                                                         {-0.1834346424956498, 0.3626837833783620}};
  const auto& half = n == 4 ? g4 : n == 6 ? g6 : g8;
  std::vector<std::pair<double, double>> out;
  for (const auto& [x, w] : half)
    for (double sign : {-1.0, 1.0}) out.push_back({0.5 * (a + b) + sign * x * 0.5 * (b - a), w * 0.5 * (b - a)});
  return out;
}

// Order 2 without paths: ∫ T(0,t) Σ_lobe σ_lobe ∫_S² P_lobe(u·v) L₁(x_t, u) du dt, L₁ the
// reference's single scattering; t by Gauss–Legendre on panels at 1, 3, 8 and 20 km, u by
// Gauss–Legendre in the zenith cosine split at the horizon (14 nodes) × 8 azimuths. Ground
// albedo 0 (the ground's part is not in L₁ here); Mie g = 0.3 so the quadrature resolves
// the phase.
Vec3 order_two_by_quadrature(const Atmosphere& a, const AtmosphereSun& sun, const Vec3& eye, const Vec3& v) {
  AtmosphereReferenceSettings coarse;
  coarse.relative_tolerance = 1e-4;
  coarse.initial_panels = 8;
  const AtmosphereReference first(a, sun, coarse);
  const double r = std::sqrt(dot(eye, eye)), mu = dot(eye, v) / r;
  const double length = physics::distance_to_boundary(a, r, mu);
  std::vector<double> edges{0};
  for (double e : {1e3, 3e3, 8e3, 20e3})
    if (e < length) edges.push_back(e);
  edges.push_back(length);
  Vec3 sum{0, 0, 0};
  for (size_t p = 0; p + 1 < edges.size(); ++p)
    for (const auto& [t, wt] : gauss_legendre(edges[p], edges[p + 1], 4)) {
      const Vec3 x = add(eye, scaled(v, t));
      const double rx = std::sqrt(dot(x, x)), h = rx - a.bottom_radius;
      const Vec3 up = scaled(x, 1 / rx), e1 = normalize(physics::cross(up, {0, 0, 1})), e2 = physics::cross(up, e1);
      const Vec3 tau = physics::optical_depth(a, r, mu, t);
      const Vec3 sr = physics::rayleigh_scattering_at(a, h), sm = physics::mie_scattering_at(a, h);
      const double horizon = physics::mu_horizon(a, rx);
      Vec3 j{0, 0, 0};
      std::vector<std::pair<double, double>> cosines = gauss_legendre(-1, horizon, 6);
      for (const auto& node : gauss_legendre(horizon, 1, 8)) cosines.push_back(node);
      for (const auto& [c_theta, wc] : cosines)
        for (int k = 0; k < 8; ++k) {
          const double phi = 2 * kPi * (k + 0.5) / 8, s_theta = std::sqrt(1 - c_theta * c_theta);
          const Vec3 u = add(scaled(up, c_theta), add(scaled(e1, s_theta * std::cos(phi)), scaled(e2, s_theta * std::sin(phi))));
          const Vec3 l1 = first.single_scattering(x, u, physics::distance_to_boundary(a, rx, c_theta));
          const double nu = dot(u, v), w = wc * 2 * kPi / 8;
          for (int c = 0; c < 3; ++c)
            j[c] += w * (sr[c] * physics::phase_rayleigh(nu) + sm[c] * physics::mie_phase(a, nu)) * l1[c];
        }
      for (int c = 0; c < 3; ++c) sum[c] += wt * std::exp(-tau[c]) * j[c];
    }
  return sum;
}

// The paths' order 2 (their phase sampling, Rayleigh's exact and Mie's by HG weighted to
// Cornette–Shanks, the forced collisions, the channels' MIS) against order_two_by_quadrature:
// within 4 standard errors (16384 paths: 1.8 % in red, 0.7 % in blue) + 2 % (the
// quadrature's own error: at most 0.42 % against 8+8 zenith nodes, 16 azimuths and 8
// nodes a panel). About 2.5 s. Measured once with 131072 paths: within 0.5 % of the
// finer quadrature in every channel (0.4-0.9 standard errors).
TEST(AtmosphereReference, PathsOrderTwoMatchesANestedQuadrature) {
  Atmosphere a = earth();
  a.ground_albedo = {0, 0, 0};
  a.mie_g = 0.3;
  const AtmosphereSun sun = sun_at(30);
  const Vec3 eye{0, a.bottom_radius + 10, 0}, v = normalize(direction_at(30, 120));
  const auto start = std::chrono::steady_clock::now();
  const Vec3 quadrature = order_two_by_quadrature(a, sun, eye, v);
  const double quadrature_seconds = elapsed_seconds_since(start);
  const ScatteringOrders paths = AtmosphereReference(a, sun, few_samples(16384)).sky(eye, v, 21).scattering;
  std::printf("order 2: paths %.5e %.5e %.5e (+- %.1e %.1e %.1e), quadrature %.5e %.5e %.5e (%.2f s), paths %.2f s\n",
              paths.radiance[1][0], paths.radiance[1][1], paths.radiance[1][2], paths.standard_error[1][0],
              paths.standard_error[1][1], paths.standard_error[1][2], quadrature[0], quadrature[1], quadrature[2],
              quadrature_seconds, elapsed_seconds_since(start) - quadrature_seconds);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(paths.radiance[1][c], quadrature[c], 4 * paths.standard_error[1][c] + 0.02 * quadrature[c]) << c;
}

TEST(AtmosphereReference, WithoutPathsTheSkyIsSingleScattering) {
  const Atmosphere a = earth();
  const AtmosphereReference reference(a, sun_at(10), few_samples(0));
  const Vec3 eye{0, a.bottom_radius + 300, 0}, v = normalize(direction_at(15, 120));  // as sky() normalises it
  const SkySample s = reference.sky(eye, v, 9);
  EXPECT_EQ(s.scattering.total, reference.single_scattering(eye, v, physics::distance_to_boundary(a, eye[1], v[1])));
  EXPECT_EQ(s.scattering.residual, (Vec3{0, 0, 0}));
  EXPECT_EQ(s.scattering.orders, 2u);
}

// Camera at 0 m, 1 mm, 10 km, 100 km and 1000 km (the last two above the earth's
// atmosphere: the ray enters at the top), looking within 1e-6 of the horizon, the sun
// below it: on the earth and on a planet of 1 km radius (its air 60 km deep).
TEST(AtmosphereReference, HorizonRaysFromTheGroundToSpaceAreFiniteAndNonNegative) {
  Atmosphere small = earth();
  small.bottom_radius = 1e3;
  small.top_radius = 1e3 + 60e3;
  const auto start = std::chrono::steady_clock::now();
  int rays = 0;
  for (const Atmosphere& a : {earth(), small}) {
    for (double sun_elevation : {-0.5, -10.0}) {
      const AtmosphereReference reference(a, sun_at(sun_elevation), few_samples(4));
      for (double altitude : {0.0, 1e-3, 10e3, 100e3, 1000e3}) {
        const double r = a.bottom_radius + altitude;
        const double horizon = -std::sqrt(std::max(0.0, 1 - std::pow(a.bottom_radius / r, 2)));
        for (double offset : {-1e-6, 0.0, 1e-6}) {
          const double mu = std::clamp(horizon + offset, -1.0, 1.0);
          const Vec3 v = normalize({0, mu, std::sqrt(1 - mu * mu)});  // across the sun's plane
          const Vec3 toward_sun = normalize({std::sqrt(1 - mu * mu), mu, 0});
          for (const Vec3& d : {v, toward_sun}) {
            const Vec3 eye{0, r, 0};
            const SkySample s = reference.sky(eye, d, uint64_t(rays));
            const AerialPerspectiveSample p = reference.aerial_perspective(eye, d, 5e3, uint64_t(rays));
            ++rays;
            EXPECT_TRUE(finite_non_negative(s.radiance)) << a.bottom_radius << " " << altitude << " " << offset;
            EXPECT_TRUE(finite_non_negative(s.transmittance)) << a.bottom_radius << " " << altitude << " " << offset;
            EXPECT_TRUE(finite_non_negative(p.in_scattered)) << a.bottom_radius << " " << altitude << " " << offset;
            EXPECT_TRUE(finite_non_negative(p.transmittance)) << a.bottom_radius << " " << altitude << " " << offset;
          }
        }
      }
    }
  }
  std::printf("horizon stress: %d rays in %.2f s\n", rays, elapsed_seconds_since(start));
  // Below the ground (a scene origin_altitude too low): the ray starts on the ground.
  const Atmosphere a = earth();
  const AtmosphereReference reference(a, sun_at(20), few_samples(4));
  const Vec3 v = direction_at(10, 30);
  const SkySample below = reference.sky({0, a.bottom_radius - 5, 0}, v, 1);
  const SkySample on = reference.sky({0, a.bottom_radius, 0}, v, 1);
  EXPECT_EQ(below.radiance, on.radiance);
  EXPECT_TRUE(finite_non_negative(reference.aerial_perspective({0, 0, 0}, v, 100, 1).in_scattered));
}

TEST(AtmosphereReference, SkyImageIsTheSameWithAnyNumberOfThreads) {
  Atmosphere atmosphere = earth();
  atmosphere.origin_altitude = 200;
  Camera camera;
  camera.position = {0, 2, 0};
  camera.target = {10, 3, 0};
  camera.fov_y_deg = 60;
  const AtmosphereReference reference(atmosphere, sun_at(25), few_samples(4));
  RenderSettings one{.width = 8, .height = 4, .threads = 1}, two = one;
  two.threads = 2;
  const SkyImage a = render_sky_image(reference, camera, one), b = render_sky_image(reference, camera, two);
  EXPECT_EQ(a.image.rgb, b.image.rgb);
  for (double c : a.image.rgb) EXPECT_TRUE(std::isfinite(c) && c > 0);
  EXPECT_GE(a.max_orders, 2u);
  // Pixel (0, 0) is the ray of pixel_ray from the camera's planet-frame position.
  const Vec3 eye = planet_position(atmosphere, camera.position);
  EXPECT_DOUBLE_EQ(eye[1], atmosphere.bottom_radius + 202);
  const SkySample s = reference.sky(eye, physics::pixel_ray(camera, 8, 4, 0, 0), 0);
  EXPECT_EQ(a.image.at(0, 0), s.radiance);
}

TEST(AtmosphereReference, SceneSunIsTheOppositeOfItsLightsDirection) {
  Atmosphere a = earth();
  Light light;
  light.direction = {0, -2, 0};
  light.irradiance = {1, 2, 3};
  const std::vector<Light> lights{light};
  EXPECT_FALSE(scene_sun(a, lights));  // sun_light −1
  a.sun_light = 1;
  EXPECT_FALSE(scene_sun(a, lights));
  a.sun_light = 0;
  const std::optional<AtmosphereSun> sun = scene_sun(a, lights);
  ASSERT_TRUE(sun);
  EXPECT_EQ(sun->direction, (Vec3{0, 1, 0}));
  EXPECT_EQ(sun->irradiance, (Vec3{1, 2, 3}));
  EXPECT_EQ(sun->angular_radius, a.sun_angular_radius);
}

}  // namespace
}  // namespace volgraph::reference
