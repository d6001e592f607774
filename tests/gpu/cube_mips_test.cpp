// cube_mips on both backends: level 0 at the input's own size is its texels; each level the
// box mean of its face's level above (one fp16 step); and a rough ball that transmits nothing
// reflects F(0°) × the chain at the level environment_lod names for its lobe (2α, α =
// roughness²), read trilinearly toward the mirrored ray (the CPU mixes the read-back levels).
// The cube is a scene_probe's (six emissive boxes around it, one along each axis).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/translucency.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/config_on_each_backend.h"
#include "tests/gpu/six_emissive_boxes.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr int kCubeMipsFace = 32;

// The probe at (0, 1, 0) amid six emissive boxes; cube_mips of it; a dark glass ball of
// `roughness` at the probe seen head-on from +z, its environment the chain.
std::string boxes_and_ball(double roughness) {
  char r[32];
  std::snprintf(r, sizeof r, "%.17g", roughness);
  return R"({ "output": { "size": [33, 33] },
  "scene": { "camera": { "position": [0, 1, 2.5], "target": [0, 1, 0], "fov_y_deg": 30 },
    "background": { "radiance": [0.01, 0.02, 0.03] },
    "materials": {
      )" + six_emissive_box_materials() + R"(,
      "dark_glass": { "albedo": [1, 1, 1], "transmission": 1, "volume": "solid", "ior": 1.5, "roughness": )" + std::string(r) + R"(,
                      "attenuation_color": [0, 0, 0], "attenuation_distance": 0.001 } },
    "objects": [
      )" + six_emissive_box_objects() + R"(,
      { "shape": "sphere", "size": [1, 1, 1], "material": "dark_glass", "transform": { "translate": [0, 1, 0] } } ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "probe", "type": "scene_probe", "params": { "position": [0, 1, 0], "size": 32 } },
    { "name": "chain", "type": "cube_mips", "params": { "size": 32, "levels": 6 }, "inputs": { "cube": "probe.cube" } },
    { "name": "glass", "type": "translucency", "inputs": { "color": "lit.color", "depth": "lit.depth", "frame": "lit.frame", "environment": "chain.mips" } } ],
    "outputs": ["glass.color", "chain.mips", "probe.cube"] } })";
}

class CubeMips : public ConfigOnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  // The image, the chain's levels 0…5 and the probe's cube after one frame.
  struct Rendered {
    Texels image;
    std::vector<Texels> levels;
    Texels probe;
  };
  Rendered render(double roughness) {
    const LoadedConfig config = load_config_text("cube_mips.json", boxes_and_ball(roughness), registry_);
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    Rendered out{executor.read_output(0), {}, executor.read_output(2)};
    for (uint32_t level = 0; level < 6; ++level) out.levels.push_back(executor.read_texture_level(config.graph.outputs[1].resource, level));
    return out;
  }
};

float cube_mips_texel(const Texels& t, int face, int i, int j, int c) {
  return t.rgba[4 * ((size_t(face) * t.height + size_t(j)) * t.width + size_t(i)) + size_t(c)];
}

TEST_P(CubeMips, EachLevelIsTheBoxMeanOfItsFaceAbove) {
  const Rendered r = render(0);
  ASSERT_EQ(r.levels[0].width, uint32_t(kCubeMipsFace));
  ASSERT_EQ(r.levels[5].width, 1u);
  for (size_t p = 0; p < r.probe.rgba.size(); ++p) ASSERT_EQ(r.levels[0].rgba[p], r.probe.rgba[p]) << "level 0 float " << p;
  for (int level = 1; level < 6; ++level) {
    const Texels &above = r.levels[size_t(level - 1)], &here = r.levels[size_t(level)];
    for (int face = 0; face < 6; ++face) {
      for (int j = 0; j < int(here.height); ++j) {
        for (int i = 0; i < int(here.width); ++i) {
          for (int c = 0; c < 3; ++c) {
            const double mean = (cube_mips_texel(above, face, 2 * i, 2 * j, c) + cube_mips_texel(above, face, 2 * i + 1, 2 * j, c) +
                                 cube_mips_texel(above, face, 2 * i, 2 * j + 1, c) + cube_mips_texel(above, face, 2 * i + 1, 2 * j + 1, c)) / 4;
            ASSERT_NEAR(cube_mips_texel(here, face, i, j, c), mean, fp16_steps(mean)) << "level " << level << " face " << face;
          }
        }
      }
    }
  }
}

// Face +z's centre (where the mirrored ray of the ball's centre pixel points) at a fractional
// level: the mean of each level's 2 × 2 central texels (1 × 1 at the last), mixed linearly.
double centre_of_face_plus_z(const std::vector<Texels>& levels, double lod, int c) {
  const auto centre = [&](size_t level) {
    const Texels& t = levels[level];
    const int h = int(t.width) / 2;
    if (t.width == 1) return double(cube_mips_texel(t, 4, 0, 0, c));
    return (cube_mips_texel(t, 4, h - 1, h - 1, c) + cube_mips_texel(t, 4, h, h - 1, c) + cube_mips_texel(t, 4, h - 1, h, c) +
            cube_mips_texel(t, 4, h, h, c)) / 4.0;
  };
  const size_t lower = size_t(std::floor(lod)), upper = std::min<size_t>(lower + 1, levels.size() - 1);
  const double f = lod - double(lower);
  return (1 - f) * centre(lower) + f * centre(upper);
}

// Roughness 0, 0.3, 0.5, 0.7: the ball's centre pixel is F(0°) = 0.04 × the chain at
// environment_lod(2α, 32) toward +z (trilinear filtering's weights: within 2 %), and its
// cyan fades as the lobe widens over the faces' other colours.
TEST_P(CubeMips, ARoughBallReflectsTheLevelItsLobeSpans) {
  double cyan_before = 1;
  for (const double roughness : {0.0, 0.3, 0.5, 0.7}) {
    const Rendered r = render(roughness);
    const double alpha = roughness * roughness;
    const double lod = physics::environment_lod(2 * alpha, kCubeMipsFace);
    const size_t at = 4 * (16 * 33 + 16);
    for (int c = 0; c < 3; ++c) {
      const double want = 0.04 * centre_of_face_plus_z(r.levels, lod, c);
      const double got = r.image.rgba[at + size_t(c)];
      std::printf("roughness %.1f (lod %.2f), channel %d: %.5f against %.5f\n", roughness, lod, c, got, want);
      EXPECT_NEAR(got, want, 0.02 * 0.04 + 2 * fp16_steps(want)) << "roughness " << roughness << " channel " << c;
    }
    EXPECT_TRUE(all_finite(r.image));
    const double cyan = r.image.rgba[at + 1];
    EXPECT_LT(cyan, cyan_before) << "roughness " << roughness;
    cyan_before = cyan;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, CubeMips, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
