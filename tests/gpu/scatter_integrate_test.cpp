// scatter_integrate (front to back along each froxel column) on both backends, through the
// froxel chain where physics gives the answer:
// - a pure absorber: the background through Beer–Lambert, e^(−σa·d), d the grid's depth
//   along each pixel's ray (fp16 volumes: 2e-3 relative);
// - a homogeneous medium under an unshadowed directional light with isotropic phase has
//   constant in-scattering S = σs·E/4π, so the radiance is S(1 − e^(−σt·d))/σt exactly:
//   Hillaire's step gets it to fp16 precision at any slice count, Wronski's errs and
//   converges as slices grow. Fixture: froxel_fog.h.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "tests/gpu/froxel_fog.h"

namespace volgraph::testing {
namespace {

class ScatterIntegrate : public FroxelFogFixture {
 protected:
  // Largest relative error of the in-scattered radiance against S(1 − e^(−σt d))/σt.
  double homogeneous_error(const std::string& variant, int slices) {
    FogCase c;
    const double sigma_s = 0.4, sigma_a = 0.1, e = 3.0;
    c.media = R"({ "fog": { "sigma_s": [0.4, 0.4, 0.4], "sigma_a": [0.1, 0.1, 0.1] } })";
    c.lights = R"([ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3], "cast_shadows": false } ])";
    c.scatter_variant = "isotropic";
    c.integrate_variant = variant;
    c.grid = R"({ "slices": )" + std::to_string(slices) + R"(, "near": 0.1, "far": 20, "distribution": "linear", "jitter": false })";
    const LoadedConfig config = load(c);
    const Texels t = render(config);
    const double s = sigma_s * e / (4 * M_PI), sigma_t = sigma_s + sigma_a;
    double worst = 0;
    for (uint32_t j = 0; j < kFroxelFogHeight; ++j) {
      for (uint32_t i = 0; i < kFroxelFogWidth; ++i) {
        const double want = column_blend(config.config.scene.camera, i, j, [&](double length) {
          return s * (1 - std::exp(-sigma_t * (20 - 0.1) * length)) / sigma_t;
        });
        worst = std::max(worst, std::abs(t.rgba[4 * (j * kFroxelFogWidth + i)] - want) / want);
      }
    }
    return worst;
  }
};

TEST_P(ScatterIntegrate, APureAbsorberAttenuatesTheBackgroundByBeerLambert) {
  FogCase c;
  c.media = R"({ "fog": { "sigma_s": [0, 0, 0], "sigma_a": [0.02, 0.05, 0.1] } })";
  c.background = "[1, 1, 1]";
  const LoadedConfig config = load(c);
  const Texels t = render(config);
  const double sigma_a[3] = {0.02, 0.05, 0.1}, depth = 20 - 0.1;
  for (uint32_t j = 0; j < kFroxelFogHeight; ++j) {
    for (uint32_t i = 0; i < kFroxelFogWidth; ++i) {
      for (size_t ch = 0; ch < 3; ++ch) {
        const double want = column_blend(config.config.scene.camera, i, j, [&](double length) { return std::exp(-sigma_a[ch] * depth * length); });
        ASSERT_NEAR(t.rgba[4 * (j * kFroxelFogWidth + i) + ch], want, 2e-3 * want) << i << ", " << j << " ch " << ch;
      }
    }
  }
}

TEST_P(ScatterIntegrate, HillaireIsExactForAHomogeneousMediumAndWronskiConverges) {
  EXPECT_LT(homogeneous_error("hillaire", 16), 3e-3);
  double previous = 1e9;
  for (int slices : {8, 16, 32, 64}) {
    const double wronski = homogeneous_error("wronski", slices);
    EXPECT_GT(wronski, 3e-3) << slices << " slices";  // optical depth 10: each slice is dense
    EXPECT_LT(wronski, previous) << slices << " slices";
    previous = wronski;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, ScatterIntegrate, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
