// Rough refraction (a solid's roughness blurs what it refracts: the level of a mip chain of
// what lies behind, generate_mips → translucency's refracted_color, whose texels span the
// refracted cone's footprint: refraction_blur_lod) on both backends, sorted and
// depth_peeling: a glass block head-on before a wall of bright and dark stripes 3 px wide.
// Roughness 0 with the chain wired is the image with a plain copy wired, bit for bit; the
// stripes' contrast through the glass falls as the roughness grows (0 → 0.3 → 0.5 → 0.8:
// levels about 1.6, 3.1 and 4.5 here); a uniform wall stays uniform through rough glass (a
// blur of a constant is that constant: within two fp16 steps of the smooth image); no NaN or
// infinity at roughness 0 and 1 × IOR 1 and 4, inside the block and at 1 × 1.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/translucency_fixture.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

// The wall: 30 stripes 0.2 m wide (bright and dark in turn), or one uniform plane.
std::string rough_wall(bool striped) {
  if (!striped) return R"({ "shape": "plane", "size": [12, 1, 12], "material": "bright", "transform": { "rotate_deg": [90, 0, 0], "translate": [0, 0, -3] } })";
  std::string stripes;
  for (int k = 0; k < 30; ++k) {
    const double x = -3.0 + 0.2 * k + 0.1;
    stripes += std::string(k ? ", " : "") + R"({ "shape": "plane", "size": [0.2, 1, 12], "material": ")" + (k % 2 ? "dark" : "bright") +
               R"(", "transform": { "rotate_deg": [90, 0, 0], "translate": [)" + std::to_string(x) + R"(, 0, -3] } })";
  }
  return stripes;
}

std::string rough_glass(const std::string& variant, double roughness, bool chain, bool striped) {
  const std::string behind = chain ? R"({ "name": "behind_glass", "type": "generate_mips", "inputs": { "color": "lit.color" } })"
                                   : R"({ "name": "behind_glass", "type": "copy", "inputs": { "source": "lit.color" } })";
  return R"({ "output": { "size": [96, 64] },
  "scene": { "camera": { "position": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40 },
    "background": { "radiance": [0.2, 0.3, 0.4] },
    "materials": { "bright": { "albedo": [0, 0, 0], "emissive": [1, 0.8, 0.6] }, "dark": { "albedo": [0, 0, 0], "emissive": [0.1, 0.1, 0.1] },
                   "glass": { "albedo": [1, 1, 1], "transmission": 1, "volume": "solid", "ior": 1.5, "roughness": )" +
         std::to_string(roughness) + R"( } },
    "objects": [ )" + rough_wall(striped) + R"(,
      { "shape": "box", "size": [1.6, 1.2, 0.5], "material": "glass" } ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" }, )" + behind + R"(,
    { "name": "glass", "type": "translucency", "variant": ")" + variant + R"(",
      "inputs": { "color": "lit.color", "depth": "lit.depth", "frame": "lit.frame", "refracted_color": ")" +
         (chain ? "behind_glass.mips" : "behind_glass.copy") + R"(" } } ],
    "outputs": ["glass.color"] } })";
}

class TranslucencyRough : public TranslucencyVariantFixture {};

// The red channel's standard deviation over the middle rows and columns of the glass (its
// image spans about ±34 px × ±26 px around the centre here; the middle ±16 × ±8).
double contrast_through_glass(const Texels& t) {
  double sum = 0, sum2 = 0;
  int n = 0;
  for (uint32_t j = t.height / 2 - 8; j < t.height / 2 + 8; ++j) {
    for (uint32_t i = t.width / 2 - 16; i < t.width / 2 + 16; ++i) {
      const double r = t.rgba[4 * (size_t(j) * t.width + i)];
      sum += r, sum2 += r * r, ++n;
    }
  }
  const double mean = sum / n;
  return std::sqrt(std::max(sum2 / n - mean * mean, 0.0));
}

TEST_P(TranslucencyRough, RoughnessZeroIsTheSmoothImageBitForBit) {
  EXPECT_EQ(render(rough_glass(variant(), 0, true, true)).rgba, render(rough_glass(variant(), 0, false, true)).rgba);
}

TEST_P(TranslucencyRough, TheStripesBlurAsTheRoughnessGrows) {
  double previous = 1e30;
  for (const double roughness : {0.0, 0.3, 0.5, 0.8}) {
    const double contrast = contrast_through_glass(render(rough_glass(variant(), roughness, true, true)));
    std::printf("rough glass %.1f: the stripes' red contrast through it %.4f\n", roughness, contrast);
    EXPECT_LT(contrast, previous) << "roughness " << roughness;
    previous = contrast;
  }
  EXPECT_LT(previous, 0.5 * contrast_through_glass(render(rough_glass(variant(), 0, true, true))));
}

TEST_P(TranslucencyRough, AUniformWallStaysUniformThroughRoughGlass) {
  const Texels smooth = render(rough_glass(variant(), 0, true, false));
  const Texels rough = render(rough_glass(variant(), 0.8, true, false));
  for (size_t p = 0; p < smooth.rgba.size(); ++p) {
    ASSERT_NEAR(rough.rgba[p], smooth.rgba[p], fp16_steps(smooth.rgba[p])) << "float " << p;
    ASSERT_TRUE(std::isfinite(rough.rgba[p]));
  }
}

// Stress: roughness 0 and 1 × IOR 1 and 4, from outside and from inside the block, at 96 × 64
// and at 1 × 1 (a chain of one level): every float finite.
TEST_P(TranslucencyRough, NoNaNAtTheExtremes) {
  for (const double roughness : {0.0, 1.0}) {
    for (const double ior : {1.0, 4.0}) {
      for (const bool inside : {false, true}) {
        for (const char* size : {"[96, 64]", "[1, 1]"}) {
          std::string text = rough_glass(variant(), roughness, true, true);
          const std::string ior_key = R"("ior": 1.5)", size_key = R"("size": [96, 64])";
          text.replace(text.find(ior_key), ior_key.size(), R"("ior": )" + std::to_string(ior));
          text.replace(text.find(size_key), size_key.size(), std::string(R"("size": )") + size);
          if (inside) {
            const std::string camera = R"("position": [0, 0, 3])";
            text.replace(text.find(camera), camera.size(), R"("position": [0, 0, 0.1], "near": 0.01)");
          }
          EXPECT_TRUE(all_finite(render(text))) << "roughness " << roughness << " ior " << ior << (inside ? " inside " : " outside ") << size;
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, TranslucencyRough,
                         ::testing::Combine(::testing::ValuesIn(gpu_backends()), ::testing::Values("sorted", "depth_peeling")),
                         TranslucencyVariantFixture::case_name);

}  // namespace
}  // namespace volgraph::testing
