// atmosphere_aerial_perspective (Hillaire 2020 §5.4, 32 × 32 × 32 over 32 km) on both
// backends, on four texels against its double twin (below). Fixture: atmosphere_lut.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/atmosphere_multiscattering.h"
#include "physics/atmosphere_sky.h"
#include "physics/camera.h"
#include "tests/gpu/atmosphere_lut.h"

namespace volgraph::testing {
namespace {

class AtmosphereAerialPerspective : public AtmosphereLutFixture {};

// The aerial-perspective volume against its double twin (physics::scattering_along with
// Ψ_ms exact, 40 midpoint samples) on four texels: each column's ray through the frame,
// slice k to (k + ½) km. In-scattering within 3e-2 relative (measured 1.9e-2: the pass
// reads Ψ_ms and the sun's transmittance from their LUTs, the twin computes them; fp16),
// transmittance within 2e-3 absolute (4.6e-4).
TEST_P(AtmosphereAerialPerspective, AerialPerspectiveMatchesTheDoubleTwin) {
  const LoadedConfig config = load(R"("atmosphere": { "preset": "earth" })");
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  const Texels scattering = executor.read_output(3), transmittance = executor.read_output(4);
  ASSERT_EQ(scattering.width, 32u);
  ASSERT_EQ(scattering.depth, 32u);
  const Scene& scene = config.config.scene;
  const Atmosphere& a = *scene.atmosphere;
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  const physics::ViewRays rays = physics::view_rays(scene.camera, 1.0);  // the frame is 16x16
  const auto psi = [&](double r, double mu_s) { return physics::multiscattering(a, r, mu_s); };
  double worst_scattering = 0, worst_transmittance = 0, largest = 0;
  for (const auto [i, j, k] : {std::array{5, 7, 0}, std::array{16, 16, 3}, std::array{30, 2, 31}, std::array{2, 29, 12}}) {
    const Vec3 d = physics::normalize(physics::view_ray(rays, (i + 0.5) / 32 * 2 - 1, 1 - (j + 0.5) / 32 * 2));
    const double mu = physics::dot(d, view.up), nu = physics::dot(d, view.toward_sun);
    const double length = std::min((k + 0.5) * 1000, physics::distance_to_boundary(a, view.r, mu));
    const physics::ScatteringAlong want = physics::scattering_along(a, view.r, mu, view.mu_s, nu, length, psi);
    const size_t at = 4 * ((size_t(k) * 32 + j) * 32 + i);
    for (size_t c = 0; c < 3; ++c) {
      largest = std::max(largest, want.radiance[c]);
      worst_scattering = std::max(worst_scattering, std::abs(scattering.rgba[at + c] - want.radiance[c]) / want.radiance[c]);
      worst_transmittance = std::max(worst_transmittance, std::abs(transmittance.rgba[at + c] - want.transmittance[c]));
    }
  }
  std::printf("aerial perspective 32x32x32 against the double twin: in-scattering %.3g relative, transmittance %.3g absolute\n",
              worst_scattering, worst_transmittance);
  EXPECT_LT(worst_scattering, 3e-2);
  EXPECT_LT(worst_transmittance, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereAerialPerspective, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
