// The atmosphere's shared includes (shaders/include/atmosphere.glsl, atmosphere_lut.glsl) on
// each backend, in float, against their CPU twins in double (physics/atmosphere.h,
// atmosphere_lut.h) at the same float inputs: the earth and mars presets, a camera from
// 0 m to 1000 km above the ground, rays from the zenith to the nadir through the horizon
// (±1e-3), the sun above and below it, every LUT's coordinates both ways. Each column's
// error |GPU − CPU| is held to rel·|CPU| + abs, the bounds stated at kColumns (about 4× the
// worst measured on lavapipe, printed by the test). Also measured and bounded: the GLSL
// transmittance at the zenith (40 panels of 4-point Gauss–Legendre) against exp of the
// closed-form optical depth in double, the LUT's zenith goal (1e-4 absolute).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "physics/atmosphere.h"
#include "physics/atmosphere_lut.h"
#include "physics/phase.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/twin_shader.h"

namespace volgraph::testing {
namespace {

using physics::LutUv;

constexpr size_t kRows = 9, kValues = 4 * kRows;  // atmosphere_twins.comp's ATMOSPHERE_TWIN_ROWS
constexpr int kPanels = 40;

// std430 mirror of atmosphere_twins.comp's TwinCase.
struct TwinCase {
  float ray[4];  // r, mu, d, mu_s
  float lut[4];  // u, v, cos_azimuth, cos θ
};

struct Column {
  const char* name;
  double relative, absolute;
};

// The bounds, per value in the shader's order, about 4× the worst measured on lavapipe
// (both backends alike; printed): float's rounding of r (~6e6 m: 0.5 m a ULP) sets the
// distances' absolute bounds (measured up to 1.7 m for a ground hit near the horizon,
// where the distance is ill-conditioned); the sky view's latitude goes through acos and
// cos, which Vulkan lets be off by thousands of ULP (lavapipe: 1.3e-4 in mu, 6.5e-5 in v,
// under 1 % of a texel); everything else is float's rounding, 1e-7 to 5e-6.
constexpr std::array<Column, kValues> kColumns{{
    {"distance_to_top", 1e-6, 1.0},   {"distance_to_ground", 1e-6, 4.0}, {"distance_to_boundary", 1e-6, 4.0}, {"enter_atmosphere", 1e-6, 1.0},
    {"radius_at", 1e-7, 1.0},         {"mu_at", 0, 3e-7},                {"altitude_at", 1e-6, 0.2},           {"mu_horizon", 0, 2e-7},
    {"T_top r", 0, 1e-6},             {"T_top g", 0, 1e-6},              {"T_top b", 0, 1e-6},                 {"sun fraction", 0, 2e-7},
    {"T_sun r", 0, 1e-6},             {"T_sun g", 0, 1e-6},              {"T_sun b", 0, 1e-6},                 {"mie_phase", 2e-6, 0},
    {"extinction r", 2e-6, 1e-12},    {"extinction g", 2e-6, 1e-12},     {"extinction b", 2e-6, 1e-12},        {"ozone density", 0, 4e-7},
    {"transmittance u", 0, 5e-7},     {"transmittance v", 0, 4e-7},      {"transmittance r", 1e-7, 1.0},       {"transmittance mu", 0, 2e-5},
    {"multiscattering u", 0, 2e-7},   {"multiscattering v", 0, 2e-7},    {"multiscattering r", 1e-7, 1.0},     {"multiscattering mu_s", 0, 3e-7},
    {"sky view u", 0, 2e-7},          {"sky view v", 0, 2.5e-4},         {"sky view mu", 0, 5e-4},             {"sky view cos_azimuth", 0, 1e-6},
    {"optical depth r", 5e-6, 1e-9},  {"optical depth g", 5e-6, 1e-9},   {"optical depth b", 5e-6, 1e-9},      {"cornette_shanks", 2e-6, 0},
}};

// The cases for one atmosphere: altitudes × view zenith cosines, the rest cycled.
std::vector<TwinCase> cases(const Atmosphere& a) {
  const double altitudes[] = {0, 1e-3, 1, 100, 1e3, 10e3, 30e3, 59e3, a.top_radius - a.bottom_radius, 100e3, 1000e3};
  const double mu_ss[] = {1, 0.5, 0.05, 0, -0.002, -0.3};
  const double cos_azimuths[] = {1, 0.6, 0, -0.4, -1};
  const double cos_thetas[] = {1, 0.9, 0.3, 0, -0.7, -1};
  std::vector<TwinCase> out;
  size_t k = 0;
  for (double h : altitudes) {
    const double r = a.bottom_radius + h, mu_h = physics::mu_horizon(a, r);
    for (double mu : {1.0, 0.7, 0.2, 0.01, 0.0, -0.01, mu_h + 1e-3, mu_h - 1e-3, -0.5, -1.0}) {
      for (double fraction : {0.0, 0.4, 1.0}) {
        const double d = fraction * physics::distance_to_boundary(a, std::min(r, a.top_radius), mu);
        const float u = float((k * 37 % 256 + 0.5) / 256), v = float((k * 11 % 64 + 0.5) / 64);
        out.push_back({{float(r), float(mu), float(d), float(mu_ss[k % 6])}, {u, v, float(cos_azimuths[k % 5]), float(cos_thetas[k % 6])}});
        ++k;
      }
    }
  }
  return out;
}

double or_minus_one(const std::optional<double>& d) { return d.value_or(-1.0); }

// The CPU twins' values for one case, in the shader's order, at its float inputs.
std::array<double, kValues> expected(const Atmosphere& a, const TwinCase& c) {
  using namespace physics;
  const double r = c.ray[0], mu = c.ray[1], d = c.ray[2], mu_s = c.ray[3];
  const LutUv uv{c.lut[0], c.lut[1]};
  const double r_in = std::min(r, a.top_radius), altitude = r_in - a.bottom_radius;
  auto transmittance_to_top_fixed = [&](double m) {
    m = std::max(m, mu_horizon(a, r_in));
    const Vec3 depth = optical_depth_fixed(a, r_in, m, distance_to_top(a, r_in, m), kPanels);
    return Vec3{std::exp(-depth[0]), std::exp(-depth[1]), std::exp(-depth[2])};
  };
  const Vec3 t_top = transmittance_to_top_fixed(mu), t_sun = transmittance_to_top_fixed(mu_s);
  const double fraction = sun_visible_fraction(a, r_in, mu_s);
  const Vec3 extinction = extinction_at(a, altitude);
  const LutUv t_uv = transmittance_lut_uv(a, r_in, std::max(mu, mu_horizon(a, r_in)));
  const RadiusAndMu t_back = transmittance_lut_r_mu(a, uv);
  const LutUv m_uv = multiscattering_lut_uv(a, r_in, mu_s);
  const RadiusAndMuS m_back = multiscattering_lut_r_mu_s(a, uv);
  const LutUv s_uv = sky_view_lut_uv(a, r_in, {mu, c.lut[2]});
  const SkyViewDirection s_back = sky_view_lut_direction(a, r_in, uv);
  const Vec3 depth = optical_depth_fixed(a, r_in, mu, distance_to_boundary(a, r_in, mu), kPanels);
  return {distance_to_top(a, r, mu), or_minus_one(distance_to_ground(a, r, mu)), distance_to_boundary(a, r, mu), or_minus_one(enter_atmosphere(a, r, mu)),
          radius_at(r, mu, d), mu_at(r, mu, d), altitude_at(a, r, mu, d), mu_horizon(a, r),
          t_top[0], t_top[1], t_top[2], fraction,
          fraction * t_sun[0], fraction * t_sun[1], fraction * t_sun[2], mie_phase(a, c.lut[3]),
          extinction[0], extinction[1], extinction[2], profile_density(a.absorption_density, altitude),
          t_uv.u, t_uv.v, t_back.r, t_back.mu,
          m_uv.u, m_uv.v, m_back.r, m_back.mu_s,
          s_uv.u, s_uv.v, s_back.mu, s_back.cos_azimuth,
          depth[0], depth[1], depth[2], phase_cornette_shanks(0.8, double(c.lut[3]))};
}

std::vector<float> run_cases(rhi::Device& device, const Atmosphere& a, const std::vector<TwinCase>& table) {
  const physics::GpuAtmosphere packed = physics::pack_atmosphere(a);
  const std::vector<std::byte> bytes =
      run_twin_shader(device, "atmosphere_twins.comp",
                      {{std::as_bytes(std::span(&packed, 1)), rhi::buffer_usage::uniform}, {std::as_bytes(std::span(table)), rhi::buffer_usage::storage}},
                      table.size(), table.size() * kValues * sizeof(float));
  std::vector<float> results(table.size() * kValues);
  std::memcpy(results.data(), bytes.data(), results.size() * sizeof(float));
  return results;
}

class AtmosphereTwins : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
};

TEST_P(AtmosphereTwins, IncludesMatchTheirCpuTwins) {
  for (const Atmosphere& a : {*physics::atmosphere_preset("earth"), *physics::atmosphere_preset("mars")}) {
    const std::vector<TwinCase> table = cases(a);
    const std::vector<float> results = run_cases(device(), a, table);
    std::array<double, kValues> worst{};  // the worst error over the column's bound's scale: |Δ| / (rel·|CPU| + abs)
    std::array<double, kValues> worst_abs{};
    for (size_t i = 0; i < table.size(); ++i) {
      const std::array<double, kValues> want = expected(a, table[i]);
      for (size_t k = 0; k < kValues; ++k) {
        const double got = results[kValues * i + k], error = std::abs(got - want[k]);
        const double bound = kColumns[k].relative * std::abs(want[k]) + kColumns[k].absolute;
        ASSERT_TRUE(std::isfinite(got)) << kColumns[k].name << " case " << i;
        worst[k] = std::max(worst[k], error / bound);
        worst_abs[k] = std::max(worst_abs[k], error);
        EXPECT_LE(error, bound) << a.preset << " " << kColumns[k].name << " case " << i << ": r " << table[i].ray[0] << " mu " << table[i].ray[1]
                                << " d " << table[i].ray[2] << " mu_s " << table[i].ray[3] << " GPU " << got << " CPU " << want[k];
      }
    }
    for (size_t k = 0; k < kValues; ++k)
      std::printf("%s %-22s worst |GPU − CPU| %.3g (%.2f of its bound)\n", a.preset.c_str(), kColumns[k].name, worst_abs[k], worst[k]);
  }
}

// The GLSL transmittance at the zenith (what fills the transmittance LUT's first column)
// against exp(−τ) with τ the closed form in double: the LUT's goal is 1e-4 absolute;
// bounded at 1e-5 (measured: printed).
TEST_P(AtmosphereTwins, ZenithTransmittanceMatchesTheClosedForm) {
  for (const Atmosphere& a : {*physics::atmosphere_preset("earth"), *physics::atmosphere_preset("mars")}) {
    std::vector<TwinCase> table;
    for (double h : {0.0, 1e-3, 1.0, 500.0, 2e3, 8e3, 20e3, 40e3}) table.push_back({{float(a.bottom_radius + h), 1.0f, 0.0f, 1.0f}, {0.5f, 0.5f, 1.0f, 1.0f}});
    const std::vector<float> results = run_cases(device(), a, table);
    double worst = 0;
    for (size_t i = 0; i < table.size(); ++i) {
      const Vec3 tau = physics::zenith_optical_depth(a, double(table[i].ray[0]) - a.bottom_radius);
      for (size_t c = 0; c < 3; ++c) {
        const double error = std::abs(results[kValues * i + 8 + c] - std::exp(-tau[c]));
        worst = std::max(worst, error);
        EXPECT_LE(error, 1e-5) << a.preset << " altitude " << double(table[i].ray[0]) - a.bottom_radius << " channel " << c;
      }
    }
    std::printf("%s zenith transmittance, GLSL float (%d panels) vs closed form in double: %.3g absolute at most\n", a.preset.c_str(), kPanels, worst);
  }
}

// The precision of planet-scale ray–sphere intersections: from 1 m above the earth's ground at
// mu = −0.1 the ground is 10.00 m away (10.00008 m in double); the GLSL twin in float
// gets it within 1e-3 relative, where the textbook quadratic in float gives 11.19 m
// (tests/unit/atmosphere_test.cpp computes that one).
TEST_P(AtmosphereTwins, GroundDistanceFromOneMetreIsStableInFloat) {
  const Atmosphere earth = *physics::atmosphere_preset("earth");
  const std::vector<TwinCase> table{{{float(earth.bottom_radius + 1), -0.1f, 0.0f, 1.0f}, {0.5f, 0.5f, 1.0f, 1.0f}}};
  const std::vector<float> results = run_cases(device(), earth, table);
  const double exact = *physics::distance_to_ground(earth, earth.bottom_radius + 1, -0.1);
  EXPECT_NEAR(results[1], exact, 1e-3 * exact);
  EXPECT_NEAR(results[2], exact, 1e-3 * exact);
  std::printf("ground from 1 m at mu = -0.1: GLSL float %.6f m, double %.6f m\n", results[1], exact);
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereTwins, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
