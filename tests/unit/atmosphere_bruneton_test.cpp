// Bruneton 2017's table parametrisations (physics/atmosphere_bruneton.h): texel centres
// round-trip through (r, mu, mu_s, nu) and back exactly (to rounding), the mu axis splits at
// v = 1/2 into the rays that hit the ground (below) and those that reach the top (above),
// with the nadir and the zenith either side of the split and the horizon at both ends,
// every coordinate stays in [0, 1], and the lookups' maths on tables filled on the CPU.
#include <cmath>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/diagnostics.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_bruneton.h"
#include "physics/phase.h"

namespace volgraph::physics {
namespace {

const Atmosphere kEarthPreset{};
const BrunetonTableSize kDefault{};
const BrunetonTableSize kSmall{4, 8, 16, 8, 16, 8};

TransmittanceToTop exact_transmittance(const Atmosphere& a) {
  return [a](double r, double mu) { return transmittance_to_top(a, r, mu); };
}

// A cheap stand-in for the lookups' tests (any transmittance will do there): e^(−k·d_top).
TransmittanceToTop cheap_transmittance(const Atmosphere& a) {
  return [a](double r, double mu) {
    const double d = distance_to_top(a, r, mu);
    return Vec3{std::exp(-4e-6 * d), std::exp(-8e-6 * d), std::exp(-16e-6 * d)};
  };
}

TEST(AtmosphereBruneton, ScatteringTexelCentresRoundTrip) {
  for (const BrunetonTableSize& size : {kDefault, kSmall}) {
    for (int z = 0; z < size.r; ++z) {
      for (int y = 0; y < size.mu; ++y) {
        // On the ground (z = 0) every ray of the ground half is the nadir (ρ = 0): no round trip there.
        if (z == 0 && y < size.mu / 2) continue;
        for (int x = 0; x < size.width(); x += 3) {
          ScatteringParams p = scattering_texel_params(kEarthPreset, x, y, z, size);
          // The unclamped nu of the texel's index, so the round trip sees the texel's own u_nu.
          p.nu = 2.0 * (x / size.mu_s) / double(size.nu - 1) - 1.0;
          const ScatteringUvwz uvwz = scattering_uvwz(kEarthPreset, p.r, p.mu, p.mu_s, p.nu, p.ray_hits_ground, size);
          EXPECT_NEAR(uvwz.r, (z + 0.5) / size.r, 1e-9) << x << " " << y << " " << z;
          // The horizon's texel from below within 1e-5: there Δ = b² − c is rounding, and the
          // ground distance takes its square root.
          EXPECT_NEAR(uvwz.mu, (y + 0.5) / size.mu, y == 0 ? 1e-5 : 1e-7) << x << " " << y << " " << z;
          EXPECT_NEAR(uvwz.mu_s, (x % size.mu_s + 0.5) / size.mu_s, 1e-7) << x << " " << y << " " << z;
          EXPECT_NEAR(uvwz.nu, double(x / size.mu_s) / double(size.nu - 1), 1e-12);
          const ScatteringLookup at = scattering_lookup_coords(uvwz, size);
          const double texel_x = (at.lerp < 0.5 ? at.x0 : at.x1) * size.width() - 0.5;
          EXPECT_NEAR(texel_x, double(x), 1e-5) << x << " " << y << " " << z;
        }
      }
    }
  }
}

TEST(AtmosphereBruneton, MuSplitsAtTheHorizon) {
  const BrunetonTableSize size = kDefault;
  for (int z : {0, 1, size.r / 2, size.r - 1}) {
    const ScatteringParams nadir = scattering_texel_params(kEarthPreset, 0, size.mu / 2 - 1, z, size);
    const ScatteringParams zenith = scattering_texel_params(kEarthPreset, 0, size.mu / 2, z, size);
    const ScatteringParams below = scattering_texel_params(kEarthPreset, 0, 0, z, size);
    const ScatteringParams above = scattering_texel_params(kEarthPreset, 0, size.mu - 1, z, size);
    EXPECT_TRUE(nadir.ray_hits_ground && below.ray_hits_ground);
    EXPECT_FALSE(zenith.ray_hits_ground || above.ray_hits_ground);
    EXPECT_NEAR(zenith.mu, 1.0, 1e-12);
    const double horizon = mu_horizon(kEarthPreset, nadir.r);
    if (z > 0) {
      EXPECT_DOUBLE_EQ(nadir.mu, -1.0);
      EXPECT_NEAR(below.mu, horizon, 1e-9);
      EXPECT_NEAR(above.mu, horizon, 1e-9);
    }
    // Every ground texel's ray hits the ground by the geometry too, every sky texel's misses
    // it (the horizon's texels aside, on it to rounding).
    for (int y = 1; y < size.mu - 1; ++y) {
      const ScatteringParams p = scattering_texel_params(kEarthPreset, 0, y, z, size);
      if (z > 0) EXPECT_EQ(p.ray_hits_ground, ray_hits_ground(kEarthPreset, p.r, p.mu)) << y << " " << z;
      EXPECT_EQ(p.ray_hits_ground, y < size.mu / 2);
    }
  }
  // A ray just above and just below the horizon lands at opposite ends of the mu axis.
  const double r = kEarthPreset.bottom_radius + 1000, horizon = mu_horizon(kEarthPreset, r);
  const ScatteringUvwz up = scattering_uvwz(kEarthPreset, r, horizon + 1e-6, 0.5, 0, false, size);
  const ScatteringUvwz down = scattering_uvwz(kEarthPreset, r, horizon - 1e-6, 0.5, 0, true, size);
  // (The ground distance changes as √ of mu's offset from the horizon: within two texels.)
  EXPECT_GT(up.mu, 1 - 2.0 / size.mu);
  EXPECT_LT(down.mu, 2.0 / size.mu);
}

TEST(AtmosphereBruneton, MuSMappingHoldsItsRangeAndIsMonotonic) {
  const BrunetonTableSize size = kDefault;
  double last = -1;
  for (int i = 0; i <= 200; ++i) {
    const double mu_s = kBrunetonMuSMin + (1 - kBrunetonMuSMin) * i / 200.0;
    const double u = scattering_uvwz(kEarthPreset, kEarthPreset.bottom_radius, 1, mu_s, 0, false, size).mu_s;
    EXPECT_GT(u, last);
    last = u;
  }
  EXPECT_NEAR(scattering_uvwz(kEarthPreset, kEarthPreset.bottom_radius, 1, kBrunetonMuSMin, 0, false, size).mu_s, 0.5 / size.mu_s, 1e-9);
  EXPECT_NEAR(scattering_uvwz(kEarthPreset, kEarthPreset.bottom_radius, 1, 1, 0, false, size).mu_s, 1 - 0.5 / size.mu_s, 1e-9);
  // Below mu_s_min: the first texel, never outside the table.
  EXPECT_NEAR(scattering_uvwz(kEarthPreset, kEarthPreset.bottom_radius, 1, -1, 0, false, size).mu_s, 0.5 / size.mu_s, 1e-9);
  EXPECT_NEAR(scattering_texel_params(kEarthPreset, 0, 0, 0, size).mu_s, kBrunetonMuSMin, 1e-9);
  EXPECT_NEAR(scattering_texel_params(kEarthPreset, size.mu_s - 1, 0, 0, size).mu_s, 1.0, 1e-9);
}

TEST(AtmosphereBruneton, CoordinatesStayInTheUnitRange) {
  const BrunetonTableSize size = kDefault;
  const Atmosphere tiny = [] {
    Atmosphere a;
    a.bottom_radius = 1e3;
    a.top_radius = 1e3 + 60e3;
    return a;
  }();
  for (const Atmosphere& a : {kEarthPreset, tiny}) {
    for (double altitude : {0.0, 1e-3, 10e3, 59.999e3, 60e3}) {
      const double r = a.bottom_radius + altitude;
      for (double mu : {-1.0, -0.5, mu_horizon(a, r) - 1e-6, mu_horizon(a, r), mu_horizon(a, r) + 1e-6, 0.0, 1e-6, 0.5, 1.0}) {
        for (double mu_s : {-1.0, -0.2, 0.0, 0.3, 1.0}) {
          const bool ground = ray_hits_ground(a, r, mu);
          const ScatteringUvwz c = scattering_uvwz(a, r, mu, mu_s, 0.3, ground, size);
          for (double x : {c.nu, c.mu_s, c.mu, c.r}) {
            EXPECT_TRUE(x >= 0 && x <= 1) << altitude << " " << mu << " " << mu_s << " " << x;
          }
          EXPECT_EQ(c.mu < 0.5, ground);
          const LutUv uv = irradiance_uv(a, r, mu_s, size);
          EXPECT_TRUE(uv.u >= 0 && uv.u <= 1 && uv.v >= 0 && uv.v <= 1);
        }
      }
    }
  }
}

TEST(AtmosphereBruneton, IrradianceTexelCentresRoundTrip) {
  const BrunetonTableSize size = kDefault;
  for (int y = 0; y < size.irradiance_height; ++y) {
    for (int x = 0; x < size.irradiance_width; ++x) {
      const LutUv uv{(x + 0.5) / size.irradiance_width, (y + 0.5) / size.irradiance_height};
      const RadiusAndMuS p = irradiance_r_mu_s(kEarthPreset, uv, size);
      const LutUv back = irradiance_uv(kEarthPreset, p.r, p.mu_s, size);
      EXPECT_NEAR(back.u, uv.u, 1e-12);
      EXPECT_NEAR(back.v, uv.v, 1e-12);
    }
  }
  EXPECT_DOUBLE_EQ(irradiance_r_mu_s(kEarthPreset, {0.5 / size.irradiance_width, 0.5 / size.irradiance_height}, size).r, kEarthPreset.bottom_radius);
  EXPECT_DOUBLE_EQ(irradiance_r_mu_s(kEarthPreset, {1 - 0.5 / size.irradiance_width, 0.5 / size.irradiance_height}, size).mu_s, 1.0);
}

TEST(AtmosphereBruneton, TableSamplingIsExactAtCentresAndLinearBetween) {
  BrunetonTable t{2, 2, 2, {}};
  for (int i = 0; i < 8; ++i) {
    for (int c = 0; c < 4; ++c) t.rgba.push_back(float(i * 4 + c));
  }
  EXPECT_DOUBLE_EQ(t.sample(0.25, 0.25, 0.25)[0], 0.0);
  EXPECT_DOUBLE_EQ(t.sample(0.75, 0.75, 0.75)[0], 28.0);
  EXPECT_DOUBLE_EQ(t.sample(0.5, 0.5, 0.5)[0], 14.0);
  EXPECT_DOUBLE_EQ(t.sample(0.0, 0.25, 0.25)[1], 1.0);  // clamped at the edge
  EXPECT_DOUBLE_EQ(t.sample(0.5, 0.25, 0.25)[2], 4.0);
}

// Scattering lookups: geometric between two positive x (mu_s) texels, linear where one is
// zero, and in y (mu) and z (r); alpha linear.
TEST(AtmosphereBruneton, ScatteringSamplingIsGeometricInMuSWherePositive) {
  // 2 × 2 × 1: x texels 1 and 4 (red), 0 and 4 (green) in row 0; row 1 doubles row 0.
  const BrunetonTable t{2, 2, 1, {1, 0, 1, 1, 4, 4, 4, 4, 2, 0, 2, 2, 8, 8, 8, 8}};
  const std::array<double, 4> midway = t.sample_scattering(0.5, 0.25, 0.5);
  EXPECT_DOUBLE_EQ(midway[0], 2.0);   // √(1 · 4)
  EXPECT_DOUBLE_EQ(midway[1], 2.0);   // (0 + 4) / 2: a zero texel blends linearly
  EXPECT_DOUBLE_EQ(midway[3], 2.5);   // alpha linear
  EXPECT_DOUBLE_EQ(t.sample_scattering(0.25, 0.25, 0.5)[0], 1.0);  // exact at centres
  EXPECT_DOUBLE_EQ(t.sample_scattering(0.5, 0.5, 0.5)[0], 3.0);    // linear in y: (2 + 4) / 2
  EXPECT_DOUBLE_EQ(t.sample(0.5, 0.25, 0.5)[0], 2.5);              // the plain lookup: linear
}

// The scattering and single Mie tables filled on the CPU by single scattering alone (the
// texel's own single_scattering), so the lookups can be checked against the quantity they
// interpolate.
struct SingleScatteringTables {
  BrunetonTable rayleigh, mie;
};
SingleScatteringTables single_scattering_tables(const Atmosphere& a, const BrunetonTableSize& size) {
  const TransmittanceToTop t = cheap_transmittance(a);
  SingleScatteringTables tables{{size.width(), size.mu, size.r, {}}, {size.width(), size.mu, size.r, {}}};
  for (int z = 0; z < size.r; ++z) {
    for (int y = 0; y < size.mu; ++y) {
      for (int x = 0; x < size.width(); ++x) {
        const SingleScattering s = single_scattering(a, t, scattering_texel_params(a, x, y, z, size));
        tables.rayleigh.rgba.insert(tables.rayleigh.rgba.end(), {float(s.rayleigh[0]), float(s.rayleigh[1]), float(s.rayleigh[2]), 0.0f});
        tables.mie.rgba.insert(tables.mie.rgba.end(), {float(s.mie[0]), float(s.mie[1]), float(s.mie[2]), 0.0f});
      }
    }
  }
  return tables;
}

TEST(AtmosphereBruneton, SkyRadianceAtATexelIsTheTexelsSingleScatteringWithPhases) {
  const BrunetonTableSize size{8, 8, 16, 4, 8, 4};
  const SingleScatteringTables scattering = single_scattering_tables(kEarthPreset, size);
  const BrunetonTable irradiance{size.irradiance_width, size.irradiance_height, 1, std::vector<float>(size_t(4 * 8 * 4), 0.0f)};
  const BrunetonTables tables{size, &scattering.rayleigh, &scattering.mie, &irradiance, cheap_transmittance(kEarthPreset)};
  // The camera on the ground, the view and the sun at a texel's (mu, mu_s, nu): the lookup
  // returns that texel (Rayleigh · p_R + Mie · p_M, every channel of both) to the float's rounding.
  const ScatteringParams p = scattering_texel_params(kEarthPreset, 2 * size.mu_s + 5, 11, 0, size);
  ASSERT_DOUBLE_EQ(p.nu, 2 * 2 / 7.0 - 1);  // a texel whose nu the clamp leaves alone
  const Vec3 camera{0, p.r, 0};
  const Vec3 view{std::sqrt(1 - p.mu * p.mu), p.mu, 0};
  const double sun_x = (p.nu - p.mu * p.mu_s) / view[0];
  const Vec3 sun{sun_x, p.mu_s, std::sqrt(std::max(0.0, 1 - sun_x * sun_x - p.mu_s * p.mu_s))};
  const BrunetonRadiance sky = sky_radiance(kEarthPreset, tables, camera, view, sun);
  const SingleScattering s = single_scattering(kEarthPreset, tables.transmittance, p);
  for (size_t c = 0; c < 3; ++c) {
    const double expected = s.rayleigh[c] * phase_rayleigh(p.nu) + s.mie[c] * mie_phase(kEarthPreset, p.nu);
    EXPECT_NEAR(sky.radiance[c], expected, 2e-6 * expected + 1e-12) << c;
  }
  EXPECT_NEAR(sky.transmittance[0], tables.transmittance(p.r, p.mu)[0], 1e-12);
}

TEST(AtmosphereBruneton, RadianceToPointIsNothingForNoDistanceAndTheSkyForTheWholeRay) {
  const BrunetonTableSize size{8, 8, 16, 4, 8, 4};
  const SingleScatteringTables scattering = single_scattering_tables(kEarthPreset, size);
  const BrunetonTable irradiance{size.irradiance_width, size.irradiance_height, 1, std::vector<float>(size_t(4 * 8 * 4), 0.0f)};
  const BrunetonTables tables{size, &scattering.rayleigh, &scattering.mie, &irradiance, cheap_transmittance(kEarthPreset)};
  const Vec3 camera{0, kEarthPreset.bottom_radius + 500, 0};
  const Vec3 view{std::sqrt(1 - 0.09), 0.3, 0};
  const Vec3 sun{0, 0.5, std::sqrt(0.75)};
  const BrunetonRadiance none = sky_radiance_to_point(kEarthPreset, tables, camera, {camera[0] + view[0] * 1e-3, camera[1] + view[1] * 1e-3, 0}, sun);
  EXPECT_LT(none.radiance[2], 1e-6);
  EXPECT_NEAR(none.transmittance[2], 1.0, 1e-6);
  const double to_top = distance_to_top(kEarthPreset, camera[1], view[1]);
  const Vec3 top{view[0] * to_top, camera[1] + view[1] * to_top, 0};
  const BrunetonRadiance whole = sky_radiance_to_point(kEarthPreset, tables, camera, top, sun);
  const BrunetonRadiance sky = sky_radiance(kEarthPreset, tables, camera, view, sun);
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(whole.radiance[c], sky.radiance[c], 1e-3 * sky.radiance[c]) << c;
  // Part of the way: between nothing and the whole ray, finite.
  const BrunetonRadiance half = sky_radiance_to_point(kEarthPreset, tables, camera, {view[0] * 5e3, camera[1] + view[1] * 5e3, 0}, sun);
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_GT(half.radiance[c], 0);
    EXPECT_LT(half.radiance[c], sky.radiance[c]);
    EXPECT_GT(half.transmittance[c], whole.transmittance[c]);
  }
}

TEST(AtmosphereBruneton, SunAndSkyIrradianceOnAHorizontalSurface) {
  const BrunetonTableSize size{8, 8, 16, 4, 8, 4};
  BrunetonTable irradiance{size.irradiance_width, size.irradiance_height, 1, {}};
  for (int i = 0; i < size.irradiance_width * size.irradiance_height; ++i) irradiance.rgba.insert(irradiance.rgba.end(), {0.1f, 0.2f, 0.3f, 0});
  const BrunetonTable scattering{size.width(), size.mu, size.r, std::vector<float>(size_t(4 * size.width() * size.mu * size.r), 0.0f)};
  const BrunetonTables tables{size, &scattering, &scattering, &irradiance, exact_transmittance(kEarthPreset)};
  const Vec3 point{0, kEarthPreset.bottom_radius, 0}, up{0, 1, 0}, sun{0, 0.6, 0.8};
  const SunAndSkyIrradiance e = sun_and_sky_irradiance(kEarthPreset, tables, point, up, sun);
  EXPECT_NEAR(e.sky[1], 0.2, 1e-7);
  const Vec3 t = transmittance_to_top(kEarthPreset, kEarthPreset.bottom_radius, 0.6);
  EXPECT_NEAR(e.sun[2], t[2] * 0.6, 1e-12);
  // A wall (normal horizontal) sees half the sky; one facing down, none.
  EXPECT_NEAR(sun_and_sky_irradiance(kEarthPreset, tables, point, {1, 0, 0}, sun).sky[1], 0.1, 1e-7);
  EXPECT_NEAR(sun_and_sky_irradiance(kEarthPreset, tables, point, {0, -1, 0}, sun).sky[1], 0.0, 1e-12);
  // The direct irradiance's cosine: mu_s above the disk's radius, 0 below −radius.
  EXPECT_NEAR(direct_irradiance(kEarthPreset, tables.transmittance, kEarthPreset.bottom_radius, 0.5)[0], 0.5 * transmittance_to_top(kEarthPreset, kEarthPreset.bottom_radius, 0.5)[0], 1e-12);
  EXPECT_EQ(direct_irradiance(kEarthPreset, tables.transmittance, kEarthPreset.bottom_radius, -0.01)[0], 0.0);
}

// The tables pass refuses a shape its x packing or its horizon split cannot hold, with one message.
std::string table_shape_error(const std::string& params) {
  PassRegistry registry;
  register_builtin_passes(registry);
  const std::string text = R"({ "output": { "size": [16, 16] },
    "scene": { "camera": { "position": [0, 1, 5], "target": [0, 1, 0] }, "atmosphere": { "preset": "earth" },
               "lights": [ { "name": "sun", "type": "directional", "direction": [0, -1, -1], "irradiance": [1, 1, 1] } ] },
    "graph": { "passes": [ { "name": "lut", "type": "atmosphere_transmittance_lut" },
                           { "name": "tables", "type": "atmosphere_bruneton_tables", "params": { )" + params + R"( },
                             "inputs": { "transmittance": "lut.transmittance" } } ],
               "outputs": ["tables.scattering"] } })";
  try {
    load_config_text("tables.json", text, registry);
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.diagnostics().size(), 1u) << e.what();
    return e.diagnostics().front().message;
  }
  return "";
}

TEST(AtmosphereBrunetonTables, ShapesTheTablesCannotHoldAreRefused) {
  EXPECT_NE(table_shape_error(R"("nu": 8, "nu_mu_s": 250)").find("must be a multiple of nu (8)"), std::string::npos);
  EXPECT_NE(table_shape_error(R"("nu": 8, "nu_mu_s": 8)").find("at least 2 mu_s texels"), std::string::npos);
  EXPECT_NE(table_shape_error(R"("mu": 127)").find("must be even"), std::string::npos);
  EXPECT_EQ(table_shape_error(R"("nu": 4, "nu_mu_s": 32, "mu": 32)"), "");
}

}  // namespace
}  // namespace volgraph::physics
