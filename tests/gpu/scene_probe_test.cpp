// scene_probe on both backends: the opaque scene seen from a point into a cube. Each face
// looks where the cube's texels do (six emissive boxes, one along each axis, fill the
// centres of their faces; a marker off the axis lands on the texel include/cube_face.h's
// twin names); face −z equals the scene pass's image of a 90° camera along −z mirrored left
// to right (the same shaders and lighting block); where no surface is, the wired sky cube's
// texel; a 1-texel probe and one inside a box stay finite. Exercises texture_cube as a
// colour attachment a face at a time, with the depth buffer's reuse planned between faces.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/cube_face.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/config_on_each_backend.h"
#include "tests/gpu/six_emissive_boxes.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

class SceneProbe : public ConfigOnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  std::vector<Texels> render(const std::string& text, size_t outputs) { return render_outputs("scene_probe.json", text, outputs); }
};

struct ProbeColor {
  float r, g, b;
};

ProbeColor probe_texel(const Texels& cube, int face, int i, int j) {
  const size_t at = 4 * ((size_t(face) * cube.height + size_t(j)) * cube.width + size_t(i));
  return {cube.rgba[at], cube.rgba[at + 1], cube.rgba[at + 2]};
}

// Six emissive boxes (albedo 0: their radiance is their emission exactly) 3 m from the probe
// along ±x, ±y, ±z, each its own colour; a small white marker toward (1, 0.5, −0.3).
std::string six_boxes(const std::string& probe_params, const std::string& extra_objects = "") {
  return R"({ "output": { "size": [32, 32] },
  "scene": { "camera": { "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 90, "near": 0.05, "far": 200 },
    "background": { "radiance": [0.01, 0.02, 0.03] },
    "materials": {
      )" + six_emissive_box_materials() + R"(,
      "marker": { "albedo": [0, 0, 0], "emissive": [4, 4, 4] }, "lit": { "albedo": [0.6, 0.5, 0.4] } },
    "lights": [ { "name": "sun", "type": "directional", "direction": [0.3, -1, -0.2], "irradiance": [2, 2, 2] } ],
    "objects": [
      )" + six_emissive_box_objects() + R"(,
      { "shape": "sphere", "size": [0.1, 0.1, 0.1], "material": "marker", "transform": { "translate": [2, 2, -0.6] } },
      { "shape": "box", "size": [0.5, 0.5, 0.5], "material": "lit", "transform": { "translate": [-0.8, 0.6, -1.5], "rotate_deg": [20, 30, 0] } })" +
         extra_objects + R"( ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "probe", "type": "scene_probe", "params": )" + probe_params + R"( } ],
    "outputs": ["probe.cube", "lit.color"] } })";
}

TEST_P(SceneProbe, EachFaceCentreSeesTheBoxOnItsAxis) {
  const std::vector<Texels> out = render(six_boxes(R"({ "position": [0, 1, 0], "size": 16 })"), 2);
  const Texels& cube = out[0];
  ASSERT_EQ(cube.depth, 6u);
  const ProbeColor want[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
  for (int face = 0; face < 6; ++face) {
    for (const auto& [i, j] : {std::pair{7, 7}, std::pair{8, 8}, std::pair{7, 8}, std::pair{8, 7}}) {
      const ProbeColor got = probe_texel(cube, face, i, j);
      EXPECT_EQ(got.r, want[face].r) << "face " << face;
      EXPECT_EQ(got.g, want[face].g) << "face " << face;
      EXPECT_EQ(got.b, want[face].b) << "face " << face;
    }
  }
}

// The marker toward (1, 0.5, −0.3) from the probe: on face +x at the texel the twin's face
// table gives (sc = −z, tc = −y over |x|), and nowhere else on that face.
TEST_P(SceneProbe, AMarkerOffTheAxisLandsOnTheTexelTheFaceTableNames) {
  const int n = 32;
  const std::vector<Texels> out = render(six_boxes(R"({ "position": [0, 1, 0], "size": 32 })"), 2);
  const glm::vec3 d = glm::normalize(glm::vec3(2, 1, -0.6f));
  ASSERT_EQ(physics::cube::cube_face_of(d), 0);
  const int i = int(std::floor((-d.z / d.x + 1) / 2 * n)), j = int(std::floor((-d.y / d.x + 1) / 2 * n));
  EXPECT_EQ(probe_texel(out[0], 0, i, j).r, 4.0f) << "texel " << i << ", " << j;
  int bright = 0;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) bright += probe_texel(out[0], 0, x, y).r > 2;
  }
  std::printf("the marker covers %d texels of face +x around (%d, %d)\n", bright, i, j);
  EXPECT_GE(bright, 1);
  EXPECT_LE(bright, 9);
}

// The scene pass's 90° camera along −z from the probe's point, 32 × 32: face −z is its image
// mirrored left to right, texel for texel but where a triangle edge passes a pixel centre
// (the two rasterize mirrored triangles, the probe's front faces wound clockwise; measured on
// lavapipe, both backends: 0 values beyond one fp16 step; bound 1 %).
TEST_P(SceneProbe, FaceMinusZIsTheScenePassImageMirrored) {
  const std::vector<Texels> out = render(six_boxes(R"({ "position": [0, 1, 0], "size": 32, "near": 0.05, "far": 200 })"), 2);
  const Texels &cube = out[0], &image = out[1];
  int off = 0;
  for (int j = 0; j < 32; ++j) {
    for (int i = 0; i < 32; ++i) {
      const ProbeColor got = probe_texel(cube, 5, 31 - i, j);
      const size_t at = 4 * (size_t(j) * 32 + size_t(i));
      const float want[3] = {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2]};
      const float have[3] = {got.r, got.g, got.b};
      for (int c = 0; c < 3; ++c) off += std::abs(have[c] - want[c]) > fp16_steps(want[c]) ? 1 : 0;
    }
  }
  std::printf("face -z against the scene pass mirrored: %d channel values beyond one fp16 step of 3072\n", off);
  EXPECT_LE(off, 30);  // 1 %: edge pixels
}

// Under an atmosphere with sky_cube wired (same size), every texel no surface covers holds
// the sky cube's texel (sampled at its own centre).
TEST_P(SceneProbe, WhereNoSurfaceIsTheSkyCubeShows) {
  std::string text = six_boxes(R"({ "position": [0, 1, 0], "size": 16 }, "inputs": { "sky": "sky.cube" })");
  const std::string atmosphere = R"("atmosphere": { "preset": "earth" },
    "background")";
  text.replace(text.find(R"("background")"), std::string(R"("background")").size(), atmosphere);
  const std::string sky_passes = R"({ "name": "lut", "type": "atmosphere_transmittance_lut" },
    { "name": "ms", "type": "atmosphere_multiscattering_lut", "inputs": { "transmittance": "lut.transmittance" } },
    { "name": "sky_view", "type": "atmosphere_skyview_lut", "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } },
    { "name": "sky", "type": "sky_cube", "params": { "size": 16 }, "inputs": { "transmittance": "lut.transmittance", "sky_view": "sky_view.sky_view", "multiscattering": "ms.multiscattering" } },
    { "name": "lit")";
  text.replace(text.find(R"({ "name": "lit")"), std::string(R"({ "name": "lit")").size(), sky_passes);
  text.replace(text.find(R"("outputs": ["probe.cube", "lit.color"])"), std::string(R"("outputs": ["probe.cube", "lit.color"])").size(),
               R"("outputs": ["probe.cube", "sky.cube"])");
  const std::vector<Texels> out = render(text, 2);
  int sky_texels = 0, off = 0;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < 16; ++j) {
      for (int i = 0; i < 16; ++i) {
        const ProbeColor probe = probe_texel(out[0], face, i, j), sky = probe_texel(out[1], face, i, j);
        const bool surface = probe.r != sky.r || probe.g != sky.g || probe.b != sky.b;
        if (!surface) ++sky_texels;
        // A surface texel differs from the sky by far more than rounding: count near misses as errors.
        if (surface && std::abs(probe.b - sky.b) < 2 * fp16_steps(sky.b) && std::abs(probe.r - sky.r) < 2 * fp16_steps(sky.r)) ++off;
      }
    }
  }
  std::printf("sky texels equal to the sky cube's: %d of 1536; within two fp16 steps but not equal: %d\n", sky_texels, off);
  EXPECT_GT(sky_texels, 1000);
  EXPECT_EQ(off, 0);
}

// The probe as translucency's environment: a glass ball that transmits nothing (its
// reflection alone) at the probe's point, seen head-on from +z: its centre pixel reflects
// back along +z, where the probe's face +z holds the cyan box — F(0°) = 0.04 × (0, 1, 1).
TEST_P(SceneProbe, ABallReflectsWhatTheProbeSees) {
  const std::string ball = R"(,
      { "shape": "sphere", "size": [1, 1, 1], "material": "dark_glass", "transform": { "translate": [0, 1, 0] } })";
  std::string text = six_boxes(R"({ "position": [0, 1, 0], "size": 32 } },
    { "name": "glass", "type": "translucency", "inputs": { "color": "lit.color", "depth": "lit.depth", "frame": "lit.frame", "environment": "probe.cube" })",
                               ball);
  text.replace(text.find(R"("lit": { "albedo")"), 0,
               R"("dark_glass": { "albedo": [1, 1, 1], "transmission": 1, "volume": "solid", "ior": 1.5, "attenuation_color": [0, 0, 0], "attenuation_distance": 0.001 }, )");
  text.replace(text.find(R"("camera": { "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 90)"),
               std::string(R"("camera": { "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 90)").size(),
               R"("camera": { "position": [0, 1, 2.5], "target": [0, 1, 0], "fov_y_deg": 30)");
  text.replace(text.find(R"([32, 32])"), 8, "[33, 33]");
  text.replace(text.find(R"("outputs": ["probe.cube", "lit.color"])"), std::string(R"("outputs": ["probe.cube", "lit.color"])").size(),
               R"("outputs": ["glass.color"])");
  const Texels image = render(text, 1)[0];
  const size_t centre = 4 * (16 * 33 + 16);
  const float r = image.rgba[centre], g = image.rgba[centre + 1], b = image.rgba[centre + 2];
  std::printf("the ball's centre: %.5f %.5f %.5f (F(0°) × cyan: 0 0.04 0.04)\n", r, g, b);
  EXPECT_LT(r, 1e-3);
  EXPECT_NEAR(g, 0.04, 2e-3);
  EXPECT_NEAR(b, 0.04, 2e-3);
}

TEST_P(SceneProbe, StaysFiniteAtItsLimits) {
  for (const std::string params : {std::string(R"({ "size": 1 })"), std::string(R"({ "position": [-0.8, 0.6, -1.5], "size": 8 })")}) {
    const std::vector<Texels> out = render(six_boxes(params), 2);
    EXPECT_TRUE(all_finite(out[0])) << params;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, SceneProbe, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
