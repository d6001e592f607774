// Dispersion (KHR_materials_dispersion) in the translucency pass, on both backends and each
// variant: a dispersive glass slab turned 35° before a bright/dark edge, seen with
// screen-space refraction (sorted, depth_peeling; weighted_oit does not refract but takes
// Fresnel per channel), equals channel by channel the plain slab's images at the channels'
// IORs (physics::dispersed_iors: red ior − halfSpread, green ior, blue ior + halfSpread)
// within two fp16 steps; with one IOR for every channel the red channel is off by far more
// at the edge. Dispersion 0 is the image without the key, bit for bit.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/translucency.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/translucency_fixture.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

// The fixture's slab before a bright/dark edge at 72 × 48 (IOR `ior`, `glass_extra` more keys),
// screen-space refraction on (the pass's default).
std::string dispersion_slab(const std::string& variant, double ior, const std::string& glass_extra) {
  return TranslucencyVariantFixture::slab_before_edge(variant, "screen_space", ior, glass_extra, "[72, 48]");
}

class TranslucencyDispersion : public TranslucencyVariantFixture {};

TEST_P(TranslucencyDispersion, EachChannelIsThePlainSlabAtThatChannelsIor) {
  const double ior = 1.5, dispersion = 4;  // V_d = 5: the channels part by several pixels
  const std::array<double, 3> iors = physics::dispersed_iors(ior, dispersion);
  const Texels dispersed = render(dispersion_slab(variant(), ior, R"(, "dispersion": 4)"));
  double worst = 0, one_ior_worst = 0;
  std::array<Texels, 3> plain;
  for (size_t c = 0; c < 3; ++c) plain[c] = render(dispersion_slab(variant(), iors[c], ""));
  for (size_t p = 0; p < dispersed.rgba.size(); p += 4) {
    for (size_t c = 0; c < 3; ++c) {
      const double want = plain[c].rgba[p + c];
      ASSERT_NEAR(dispersed.rgba[p + c], want, fp16_steps(want)) << "value " << p / 4 << " channel " << c;
      worst = std::max(worst, double(std::abs(dispersed.rgba[p + c] - want)));
    }
    one_ior_worst = std::max(one_ior_worst, double(std::abs(plain[1].rgba[p] - plain[0].rgba[p])));
  }
  std::printf("dispersion %s: worst channel off its IOR's image %.3g; the red at one IOR would be %.3g off\n", variant().c_str(), worst,
              one_ior_worst);
  // The identity can fail: red at the green's IOR differs by many fp16 steps (Fresnel everywhere,
  // the edge's sub-pixel shift where refracting; measured 0.067 refracting, 5.4e-3 weighted_oit).
  EXPECT_GT(one_ior_worst, variant() == "weighted_oit" ? 3e-3 : 3e-2);
}

TEST_P(TranslucencyDispersion, DispersionZeroIsTodaysImageBitForBit) {
  const Texels without = render(dispersion_slab(variant(), 1.5, ""));
  const Texels zero = render(dispersion_slab(variant(), 1.5, R"(, "dispersion": 0)"));
  ASSERT_EQ(zero.rgba.size(), without.rgba.size());
  for (size_t p = 0; p < zero.rgba.size(); ++p) ASSERT_EQ(zero.rgba[p], without.rgba[p]) << "float " << p;
}

INSTANTIATE_TEST_SUITE_P(Backends, TranslucencyDispersion,
                         ::testing::Combine(::testing::ValuesIn(gpu_backends()), ::testing::Values("sorted", "weighted_oit", "depth_peeling")), TranslucencyVariantFixture::case_name);

}  // namespace
}  // namespace volgraph::testing
