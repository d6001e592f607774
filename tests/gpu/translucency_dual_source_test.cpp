// The translucency pass's layers in one draw (dual-source blending: radiance + colour ×
// transmittance) against two (× transmittance, then + radiance), on both backends, sorted
// and depth_peeling, over a scene of lit coloured sheets (both faces drawn) and a solid
// Fresnel-reflecting absorbing box:
// - the images agree to one fp16 step of the colour target (rgba16_float) per layer a
//   pixel has, in every channel: the box alone (one layer) to one step, the three objects
//   to three (the largest difference and the bit-identical share are printed);
// - the plan the executor runs says which it chose and why (Plan::setup_notes): one draw
//   where the device offers dual-source blending and `dual_source` is on, else two with
//   the reason; weighted_oit says it has no per-layer blend to fuse.
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

// Lit sheets of coverage and transmission crossing a solid glass box, before an emissive wall.
std::string dual_source_scene(const std::string& variant, bool dual_source, bool box_alone) {
  const std::string sheets = box_alone ? "" : R"(
                          { "shape": "plane", "size": [2, 1, 2], "material": "red",
                            "transform": { "rotate_deg": [90, 20, 0], "translate": [0.3, 0, 0.5] } },
                          { "shape": "plane", "size": [2, 1, 2], "material": "blue",
                            "transform": { "rotate_deg": [90, -15, 0], "translate": [-0.3, 0, 0] } },)";
  return R"({ "output": { "size": [32, 24] },
  "scene": { "camera": { "position": [0.4, 0.3, 3], "target": [0, 0, 0], "fov_y_deg": 45 },
             "background": { "radiance": [0.2, 0.3, 0.4] },
             "lights": [ { "type": "directional", "direction": [0.3, -0.4, -1], "irradiance": [2, 2, 2] } ],
             "materials": { "wall": { "albedo": [0, 0, 0], "emissive": [1, 0.9, 0.8] },
                            "red": { "albedo": [1, 0.2, 0.1], "alpha": 0.5, "transmission": 0.5 },
                            "blue": { "albedo": [0.1, 0.3, 1], "alpha": 0.7, "transmission": 0.3 },
                            "glass": { "albedo": [1, 1, 1], "transmission": 1, "ior": 1.5, "volume": "solid",
                                       "attenuation_color": [0.9, 0.5, 0.2], "attenuation_distance": 0.4 } },
             "objects": [ { "shape": "plane", "size": [100, 1, 100], "material": "wall",
                            "transform": { "rotate_deg": [90, 0, 0], "translate": [0, 0, -1] } },)" + sheets + R"(
                          { "shape": "box", "size": [0.8, 0.8, 0.6], "material": "glass",
                            "transform": { "rotate_deg": [10, 30, 0], "translate": [0, -0.2, 0.2] } } ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "glass", "type": "translucency", "variant": ")" + variant + R"(",
      "params": { "dual_source": )" + (dual_source ? "true" : "false") + R"( },
      "inputs": { "color": "lit.color", "depth": "lit.depth", "frame": "lit.frame" } } ],
    "outputs": ["glass.color"] } })";
}

class TranslucencyDualSource : public TranslucencyVariantFixture {
 protected:
  struct Rendered {
    Texels image;
    std::string note;  // the translucency pass's setup note
  };
  Rendered render(bool dual_source, bool box_alone = false) {
    const LoadedConfig loaded = load_config_text("dual_source.json", dual_source_scene(variant(), dual_source, box_alone), registry_);
    scene_ = loaded.config.scene;
    Executor executor(device(), loaded.graph, &scene_, {});
    executor.run_frame();
    Rendered out{executor.read_output(0), ""};
    for (const SetupNote& n : executor.plan().setup_notes) {
      if (loaded.graph.passes[n.pass].name.starts_with("glass")) out.note = n.text;
    }
    return out;
  }
};

// One draw rounds L + C·T to fp16 once; two draws round C·T first, then C·T + L. The
// target's conversion rounds toward zero on lavapipe (to nearest elsewhere): the first
// rounding is under one step of C·T ≤ one step of the sum (both ≥ 0), so one layer's two
// results differ by at most one fp16 step of the larger; each layer over it adds its own
// (the difference below scaled by its transmittance ≤ 1). Bit for bit wherever the
// rounding of C·T is exact.
void expect_within_steps_per_layer(const Texels& one, const Texels& two, double layers, const std::string& what) {
  ASSERT_EQ(one.rgba.size(), two.rgba.size());
  double worst_steps = 0;
  size_t identical = 0, channels = 0;
  for (size_t p = 0; p < one.rgba.size(); ++p) {
    if (p % 4 == 3) {
      EXPECT_EQ(one.rgba[p], two.rgba[p]) << "alpha " << p / 4;  // kept by both: 0 + a × 1, a × 1 + 0
      continue;
    }
    const double a = one.rgba[p], b = two.rgba[p];
    const double step = fp16_steps(std::max(std::abs(a), std::abs(b))) / 2;  // one step of the rgba16_float colour
    worst_steps = std::max(worst_steps, std::abs(a - b) / step);
    identical += a == b;
    ++channels;
    EXPECT_LE(std::abs(a - b), layers * step) << "pixel " << p / 4 << " channel " << p % 4 << ": " << a << " (one draw) " << b << " (two)";
  }
  std::printf("%s: one draw a layer against two: %zu of %zu channels bit for bit, largest difference %.2f fp16 steps (bound %.0f)\n",
              what.c_str(), identical, channels, worst_steps, layers);
  // The objects do change the image: the comparison is not of two empty passes.
  EXPECT_NE(one.rgba[4 * (one.height / 2 * one.width + one.width / 2)], 1.0f);
}

TEST_P(TranslucencyDualSource, OneDrawALayerMatchesTwoToAnFp16StepALayer) {
  const std::string what = std::string(backend_name(backend())) + " " + variant();
  const Rendered one = render(true, true), two = render(false, true);
  expect_within_steps_per_layer(one.image, two.image, 1, what + ", the box alone (" + one.note + ")");
  // The sheets and the box: at most three layers a pixel (each sheet one face, the box its front faces).
  expect_within_steps_per_layer(render(true).image, render(false).image, 3, what + ", two sheets and the box");
}

// The choice and its reason, as `volgraph plan --setup` prints them.
TEST_P(TranslucencyDualSource, ThePlanSaysHowManyDrawsALayerTakesAndWhy) {
  const bool offered = device().has_dual_source_blending();
  const std::string on = render(true).note, off = render(false).note;
  if (variant() == "weighted_oit") {
    EXPECT_EQ(on, "weighted_oit: its own accumulation, no per-layer blend to fuse");
    EXPECT_EQ(off, on);
    return;
  }
  EXPECT_EQ(off, "two draws a layer (× transmittance, + radiance): dual_source is off");
  const std::string name(backend_name(backend()));
  EXPECT_EQ(on, offered ? "one draw a layer (radiance + colour × transmittance): dual-source blending, offered by the " + name + " device" +
                                    (variant() == "sorted" ? " (non-convex objects: two, as before)" : "")
                        : "two draws a layer (× transmittance, + radiance): the " + name + " device does not offer dual-source blending");
  std::printf("%s: dual-source blending %s\n", name.c_str(), offered ? "offered" : "not offered");
}

INSTANTIATE_TEST_SUITE_P(Backends, TranslucencyDualSource,
                         ::testing::Combine(::testing::ValuesIn(gpu_backends()), ::testing::Values("sorted", "depth_peeling", "weighted_oit")),
                         TranslucencyVariantFixture::case_name);

}  // namespace
}  // namespace volgraph::testing
