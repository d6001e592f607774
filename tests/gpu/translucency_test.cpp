// The translucency pass against what optics gives exactly (RTR4 §14.5.1), on both
// backends, with each variant (sorted, weighted_oit, depth_peeling at its default layers),
// over an emissive wall of radiance 1
// (reflecting nothing) seen through one translucent box or sheet; tolerances are two fp16
// steps of the colour target (rgba16_float) unless stated:
// - a solid slab of σt = −ln(c)/d and thickness d, IOR 1, transmission 1, albedo 1: every
//   pixel shows e^(−σt·d/|cos θ|), the path at the pixel's angle (c at normal incidence;
//   weighted_oit within the half-float rounding of its summed optical depth);
// - IOR 1.5, no absorption: the wall dimmed by (1 − F) (one interface, as glTF) and the background reflected by F,
//   F Schlick's at each pixel's angle (0.04 at normal incidence);
// - IOR 1, transmission 1, albedo 1, no absorption: the colour is bit for bit the colour
//   without the sheet (the pass is culled there);
// - coverage 0.25 of a lit white sheet: 0.75·wall + 0.25·ρ/π·E exactly as the layer says;
// - order: sorted and depth_peeling draw the same image whatever the objects' order in the
//   config (bit for bit), weighted_oit within 1e-3 (half-float sums in another order round
//   differently);
// - two sheets crossing each other: depth_peeling matches the CPU reference (each pixel's
//   layers in their own order), sorted cannot (one order per object);
// - stress: attenuation colour 0, a shell 1 nm thick, IOR 4, a grazing view and a camera
//   inside a solid (depth_peeling also with 1 and 16 layers): every value finite.
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/camera.h"
#include "physics/translucency.h"
#include "passes/plumbing/gltf.h"
#include "reference/image_render.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/translucency_fixture.h"
#include "tests/support/source_dir.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kTranslucencyWidth = 24, kTranslucencyHeight = 16;

// A camera 3 m in front of an emissive wall at z = −1 and `objects` (JSON) between,
// through scene → translucency (variant) → linear colour.
constexpr const char* kCamera = R"("camera": { "position": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40 },)";

std::string config(const std::string& materials, const std::string& objects, const std::string& variant,
                   const std::string& extra_scene = "", const std::string& camera = kCamera) {
  return R"({ "output": { "size": [24, 16] },
  "scene": { )" + camera + R"(
             "background": { "radiance": [0.2, 0.3, 0.4] }, )" + extra_scene + R"(
             "materials": { "wall": { "albedo": [0, 0, 0], "emissive": [1, 1, 1] }, )" + materials + R"( },
             "objects": [ { "shape": "plane", "size": [100, 1, 100], "material": "wall",
                            "transform": { "rotate_deg": [90, 0, 0], "translate": [0, 0, -1] } } )" + objects + R"( ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "glass", "type": "translucency", "variant": ")" + variant + R"(",
      "inputs": { "color": "lit.color", "depth": "lit.depth", "frame": "lit.frame" } } ],
    "outputs": ["glass.color"] } })";
}

// `text` with the translucency pass's depth_peeling layer count set to `layers` (none: as it is).
std::string with_layers(std::string text, const std::string& layers) {
  const std::string variant = R"("variant": "depth_peeling")";
  const size_t at = text.find(variant);
  if (layers.empty() || at == std::string::npos) return text;
  return text.insert(at + variant.size(), R"(, "params": { "layers": )" + layers + " }");
}


class Translucency : public TranslucencyVariantFixture {
 protected:
  // |cos θ| of pixel (i, j)'s ray to the slab's normal (z).
  double cos_to_z(uint32_t i, uint32_t j, uint32_t width = kTranslucencyWidth, uint32_t height = kTranslucencyHeight) const {
    return std::abs(physics::pixel_ray(scene_.camera, width, height, i, j)[2]);
  }

};

double at(const Texels& t, uint32_t i, uint32_t j, size_t c) { return t.rgba[4 * (j * t.width + i) + c]; }

TEST_P(Translucency, ASolidSlabAbsorbsAlongThePathAtEachAngle) {
  const std::array<double, 3> c{0.5, 0.25, 0.125};
  const double d = 0.5;
  // weighted_oit sums optical depths −ln T in a half-float target: T carries the relative
  // error of two fp16 steps of −ln T (1.9e-3 at T = 0.11) on top of the colour's.
  auto tolerance = [&](double want) {
    const double oit = variant() == "weighted_oit" ? want * fp16_steps(-std::log(want)) : 0;
    return fp16_steps(want) + 2e-4 * want + oit;
  };
  const Texels image = render(config(R"("glass": { "albedo": [1, 1, 1], "transmission": 1, "ior": 1, "volume": "solid",
                                                  "attenuation_color": [0.5, 0.25, 0.125], "attenuation_distance": 0.5 })",
                                     R"(, { "shape": "box", "size": [20, 20, 0.5], "material": "glass" })", variant()));
  for (uint32_t j = 0; j < kTranslucencyHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucencyWidth; ++i) {
      for (size_t k = 0; k < 3; ++k) {
        const double want = physics::slab_transmittance(physics::sigma_t_from_color(c[k], d), d, cos_to_z(i, j));
        EXPECT_NEAR(at(image, i, j, k), want, tolerance(want)) << "pixel " << i << "," << j << " channel " << k;
      }
    }
  }
}

// A solid slab 1 m thick 30 m away (near 0.05 m), T down to 4e-4 (σt·d = 7.8): a 32-bit
// depth there resolves ~1 mm, ~1e-3 of the path and ~1e-2 of T (measured before the back
// faces' float distance: 9 fp16 steps at worst). Each pixel's e^(−σt·d/|cos θ|) within two
// fp16 steps: one the colour target's own conversion (lavapipe rounds toward zero), one
// for the path (≤ 1.3e-4 of it on the deepest channel). weighted_oit sums −ln T in half
// float: one step of it (4e-3 of T here) on top.
TEST_P(Translucency, AFarSolidAbsorbsAlongItsPathToAnFp16Step) {
  const std::array<double, 3> c{0.5, 0.1, 0.02};
  const double distance = 0.5, thickness = 1.0;
  const std::string far_camera = R"("camera": { "position": [0, 0, 30], "target": [0, 0, 0], "fov_y_deg": 4, "near": 0.05 },)";
  const Texels image = render(config(R"("glass": { "albedo": [1, 1, 1], "transmission": 1, "ior": 1, "volume": "solid",
                                                  "attenuation_color": [0.5, 0.1, 0.02], "attenuation_distance": 0.5 })",
                                     R"(, { "shape": "box", "size": [20, 20, 1], "material": "glass" })", variant(), "", far_camera));
  double worst_steps = 0;
  for (uint32_t j = 0; j < kTranslucencyHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucencyWidth; ++i) {
      for (size_t k = 0; k < 3; ++k) {
        const double want = physics::slab_transmittance(physics::sigma_t_from_color(c[k], distance), thickness, cos_to_z(i, j));
        const double step = fp16_steps(want) / 2;  // one step of the rgba16_float colour at `want`
        const double oit = variant() == "weighted_oit" ? want * fp16_steps(-std::log(want)) / 2 : 0;  // one step of −ln T
        worst_steps = std::max(worst_steps, std::abs(at(image, i, j, k) - want) / step);
        EXPECT_NEAR(at(image, i, j, k), want, 2 * step + oit) << "pixel " << i << "," << j << " channel " << k;
      }
    }
  }
  std::printf("solid 30 m away (%s): worst |rendered - exact| %.2f fp16 steps\n", variant().c_str(), worst_steps);
}

// A solid slab of IOR 1.5 turned 45° about y: the ray refracts (Snell), so it absorbs
// along the slab's thickness over cos θt, not over cos θi (RTR4 §14.5.2): closed form
// F L_env + (1 − F) e^(−σt d / cos θt) at each pixel's angle to the slab's normal.
TEST_P(Translucency, ASolidAbsorbsAlongTheRefractedPath) {
  const double c = 0.25, d = 0.3;  // σt d = ln 4
  const Texels image = render(config(R"("glass": { "albedo": [1, 1, 1], "transmission": 1, "ior": 1.5, "volume": "solid",
                                                  "attenuation_color": [0.25, 0.25, 0.25], "attenuation_distance": 0.3 })",
                                     R"(, { "shape": "box", "size": [2, 2, 0.3], "material": "glass", "transform": { "rotate_deg": [0, 45, 0] } })",
                                     variant()));
  const std::array<double, 3> normal{std::sqrt(0.5), 0, std::sqrt(0.5)}, background{0.2, 0.3, 0.4};
  double worst_straight = 1;
  for (uint32_t j = 5; j <= 11; ++j) {
    for (uint32_t i = 9; i <= 14; ++i) {  // rays through the front and back faces (not the side faces)
      const std::array<double, 3> ray = physics::pixel_ray(scene_.camera, kTranslucencyWidth, kTranslucencyHeight, i, j);
      const double cos_i = std::abs(ray[0] * normal[0] + ray[1] * normal[1] + ray[2] * normal[2]);
      const double f = physics::interface_reflectance(1.5, cos_i);
      const double absorbed = physics::slab_transmittance(physics::sigma_t_from_color(c, d), d, physics::refracted_cosine(1.5, cos_i));
      const double straight = physics::slab_transmittance(physics::sigma_t_from_color(c, d), d, cos_i);
      for (size_t k = 0; k < 3; ++k) {
        const double want = f * background[k] + (1 - f) * absorbed;
        const double tolerance = fp16_steps(want) + 2e-3 * want + (variant() == "weighted_oit" ? want * fp16_steps(-std::log(want)) : 0);
        EXPECT_NEAR(at(image, i, j, k), want, tolerance) << "pixel " << i << "," << j << " channel " << k;
        worst_straight = std::min(worst_straight, std::abs(f * background[k] + (1 - f) * straight - want) / want);
      }
    }
  }
  EXPECT_GT(worst_straight, 0.1);  // the straight path's answer lies far outside the tolerance
}

TEST_P(Translucency, GlassReflectsFresnelsShareAndPassesTheRest) {
  const Texels image = render(config(R"("glass": { "albedo": [1, 1, 1], "transmission": 1, "ior": 1.5, "volume": "solid" })",
                                     R"(, { "shape": "box", "size": [20, 20, 0.5], "material": "glass" })", variant()));
  const std::array<double, 3> background{0.2, 0.3, 0.4};
  EXPECT_DOUBLE_EQ(physics::interface_reflectance(1.5, 1.0), 0.04);
  for (uint32_t j = 0; j < kTranslucencyHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucencyWidth; ++i) {
      const double f = physics::interface_reflectance(1.5, cos_to_z(i, j));
      for (size_t k = 0; k < 3; ++k) {
        const double want = f * background[k] + (1 - f);  // one interface (KHR_materials_volume): no exit F
        EXPECT_NEAR(at(image, i, j, k), want, fp16_steps(want) + 1e-4) << "pixel " << i << "," << j << " channel " << k;
      }
    }
  }
}

TEST_P(Translucency, IndexOneLeavesTheBackgroundUnchangedBitForBit) {
  const std::string sheet = R"(, { "shape": "plane", "size": [20, 1, 20], "material": "clear", "transform": { "rotate_deg": [90, 0, 0] } })";
  const Texels with = render(config(R"("clear": { "albedo": [1, 1, 1], "transmission": 1, "ior": 1 })", sheet, variant()));
  const Texels without = render(config(R"("clear": { "albedo": [1, 1, 1] })", "", variant()));
  ASSERT_EQ(with.rgba.size(), without.rgba.size());
  for (size_t p = 0; p < with.rgba.size(); ++p) ASSERT_EQ(with.rgba[p], without.rgba[p]) << "float " << p;
}

// alphaMode mask on a transmitting material: coverage below the cutoff is a hole (the
// image bit for bit as without the sheet), above it the sheet is fully covered (the same
// image as alpha_mode opaque).
TEST_P(Translucency, MaskedTexelsOfATransmittingSurfaceAreHoles) {
  const std::string sheet = R"(, { "shape": "plane", "size": [20, 1, 20], "material": "tinted", "transform": { "rotate_deg": [90, 0, 0] } })";
  const Texels cut = render(config(R"("tinted": { "albedo": [1, 0.5, 0.25], "transmission": 1, "alpha": 0.3, "alpha_mode": "mask" })", sheet, variant()));
  const Texels without = render(config(R"("tinted": { "albedo": [1, 1, 1] })", "", variant()));
  const Texels kept = render(config(R"("tinted": { "albedo": [1, 0.5, 0.25], "transmission": 1, "alpha": 0.7, "alpha_mode": "mask" })", sheet, variant()));
  const Texels opaque = render(config(R"("tinted": { "albedo": [1, 0.5, 0.25], "transmission": 1, "alpha": 0.7, "alpha_mode": "opaque" })", sheet, variant()));
  ASSERT_EQ(cut.rgba.size(), without.rgba.size());
  for (size_t p = 0; p < cut.rgba.size(); ++p) ASSERT_EQ(cut.rgba[p], without.rgba[p]) << "float " << p;
  for (size_t p = 0; p < kept.rgba.size(); ++p) ASSERT_EQ(kept.rgba[p], opaque.rgba[p]) << "float " << p;
  EXPECT_NE(kept.rgba, without.rgba);
}

TEST_P(Translucency, CoverageBlendsTheLitSurfaceOverWhatIsBehind) {
  // A white sheet facing the camera, lit head-on by E = π: ρ/π·E = 1 where covered.
  const std::string light = R"("lights": [ { "type": "directional", "direction": [0, 0, -1], "irradiance": [3.14159265, 3.14159265, 3.14159265] } ],)";
  const Texels image = render(config(R"("veil": { "albedo": [1, 0.5, 0.25], "alpha": 0.25, "ior": 1 })",
                                     R"(, { "shape": "plane", "size": [20, 1, 20], "material": "veil", "transform": { "rotate_deg": [90, 0, 0] } })",
                                     variant(), light));
  const std::array<double, 3> albedo{1, 0.5, 0.25};
  for (uint32_t j = 0; j < kTranslucencyHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucencyWidth; ++i) {
      for (size_t k = 0; k < 3; ++k) {
        const double want = 0.75 * 1.0 + 0.25 * albedo[k] * 3.14159265 / M_PI;  // the wall is lit too, but reflects nothing
        EXPECT_NEAR(at(image, i, j, k), want, fp16_steps(want)) << "pixel " << i << "," << j << " channel " << k;
      }
    }
  }
}

// Two overlapping coloured sheets, in the config's order or reversed.
std::string two_sheets(const std::string& variant, bool reversed) {
  const std::string near = R"(, { "shape": "plane", "size": [2, 1, 2], "material": "red", "transform": { "rotate_deg": [90, 0, 0], "translate": [0.3, 0, 0.5] } })";
  const std::string far = R"(, { "shape": "plane", "size": [2, 1, 2], "material": "blue", "transform": { "rotate_deg": [90, 0, 0], "translate": [-0.3, 0, 0] } })";
  const std::string light = R"("lights": [ { "type": "directional", "direction": [0, 0, -1], "irradiance": [2, 2, 2] } ],)";
  return config(R"("red": { "albedo": [1, 0.2, 0.1], "alpha": 0.5, "transmission": 0.5 }, "blue": { "albedo": [0.1, 0.3, 1], "alpha": 0.7, "transmission": 0.3 })",
                reversed ? far + near : near + far, variant, light);
}

TEST_P(Translucency, TheImageDoesNotDependOnTheObjectsOrder) {
  const Texels forward = render(two_sheets(variant(), false));
  const Texels reversed = render(two_sheets(variant(), true));
  ASSERT_EQ(forward.rgba.size(), reversed.rgba.size());
  const double tolerance = variant() == "weighted_oit" ? 1e-3 : 0.0;
  for (size_t p = 0; p < forward.rgba.size(); ++p) {
    ASSERT_NEAR(forward.rgba[p], reversed.rgba[p], tolerance * std::max(1.0f, std::abs(forward.rgba[p]))) << "float " << p;
  }
}

TEST_P(Translucency, StaysFiniteAtTheLimits) {
  const std::string materials = R"("black": { "albedo": [1, 1, 1], "transmission": 1, "volume": "solid", "attenuation_color": [0, 0, 0], "attenuation_distance": 1e-3 },
    "shell": { "albedo": [1, 1, 1], "transmission": 1, "volume": "shell", "thickness": 1e-9, "attenuation_color": [0, 0.5, 1], "attenuation_distance": 1e-6 },
    "opaque_glass": { "albedo": [0.5, 0.5, 0.5], "transmission": 0, "alpha": 0, "ior": 4 })";
  const std::string objects = R"(, { "shape": "box", "size": [0.5, 0.5, 0.5], "material": "black", "transform": { "translate": [-0.6, 0, 0] } },
    { "shape": "sphere", "size": [0.4, 0.4, 0.4], "material": "shell", "transform": { "translate": [0.6, 0, 0] } },
    { "shape": "plane", "size": [20, 1, 20], "material": "opaque_glass", "transform": { "translate": [0, -0.5, 0] } })";
  for (const std::string& camera : {std::string(kCamera), std::string(R"("camera": { "position": [-0.6, 0, 0], "target": [-0.6, 0, -1], "fov_y_deg": 170, "near": 0.01 },)"),
                                   std::string(R"("camera": { "position": [0, -0.49, 3], "target": [0, -0.5, -3], "fov_y_deg": 40 },)")}) {
    for (const std::string& layers : variant() == "depth_peeling" ? std::vector<std::string>{"1", "8", "16"} : std::vector<std::string>{""}) {
      const Texels image = render(with_layers(config(materials, objects, variant(), "", camera), layers));
      for (size_t p = 0; p < image.rgba.size(); ++p) ASSERT_TRUE(std::isfinite(image.rgba[p])) << "float " << p << " layers " << layers;
    }
  }
}

// Two tinted sheets through the same centre, turned ±40° about the vertical: one is in front
// on one side of the line where they cross, the other on the other side. The light casts no
// shadows (translucent surfaces shadow nothing on the GPU, a known limit; the reference would
// tint the light reaching the far sheet). Against the CPU reference's straight layers, by the
// relative mean error Σ|gpu − ref| / Σ ref and the worst texel's |gpu − ref| / ref (measured on
// lavapipe: peeling 3.5e-4 and 2.2e-3, sorted 2.1e-2 and 0.38, weighted_oit 1.3e-2 and 0.25):
// depth_peeling orders each pixel's layers and is exact to half-float rounding, sorted orders
// the objects once (their centres tie) and is wrong on one side, weighted_oit averages the two
// radiances by depth weight.
std::string crossing_sheets(const std::string& variant) {
  const std::string light = R"("lights": [ { "type": "directional", "direction": [0, 0, -1], "irradiance": [2, 2, 2], "cast_shadows": false } ],)";
  return config(R"("red": { "albedo": [1, 0.2, 0.1], "alpha": 0.6, "transmission": 0.5, "ior": 1 },
                   "blue": { "albedo": [0.1, 0.3, 1], "alpha": 0.7, "transmission": 0.3, "ior": 1 })",
                R"(, { "shape": "plane", "size": [2, 1, 2], "material": "red", "transform": { "rotate_deg": [90, 40, 0] } },
                   { "shape": "plane", "size": [2, 1, 2], "material": "blue", "transform": { "rotate_deg": [90, -40, 0] } })",
                variant, light);
}

TEST_P(Translucency, CrossingSheetsAreOrderedPerPixel) {
  const Texels image = render(crossing_sheets(variant()));
  const reference::ReferenceImage truth = reference::render_image(reference::Renderer(scene_, {}), {image.width, image.height});
  double error = 0, total = 0, worst = 0;
  for (uint32_t j = 0; j < image.height; ++j) {
    for (uint32_t i = 0; i < image.width; ++i) {
      for (size_t k = 0; k < 3; ++k) {
        const double off = std::abs(at(image, i, j, k) - truth.at(i, j)[k]);
        error += off;
        total += truth.at(i, j)[k];
        worst = std::max(worst, off / truth.at(i, j)[k]);
      }
    }
  }
  const double relative = error / total;
  std::printf("crossing sheets, %s: relative mean error %.2e, worst texel %.2e against the reference\n", variant().c_str(), relative, worst);
  if (variant() == "depth_peeling") EXPECT_LT(relative, 2e-3);
  if (variant() == "depth_peeling") EXPECT_LT(worst, 4e-3);  // a few half-float steps
  if (variant() == "sorted") EXPECT_GT(worst, 5e-2);  // the case needs each pixel's own order
  if (variant() == "weighted_oit") EXPECT_LT(relative, 3e-2);
}

// A sheet of coverage 1 (blend, IOR 1: no reflection) drawn by the translucency pass in
// homogeneous fog (configs/graphs/translucency_froxel_fog.json) is fogged at its own depth
// exactly as the same sheet drawn opaque is by froxel_apply: the same froxel lookup at the
// same depth (froxel_sample.glsl). Behind it, 2 m further, a black wall shows the fog
// alone: a pass that fogged the sheet at the opaque depth, or not at all, is far off
// (checked below). The opaque sheet casts no shadow (cast_shadows false), as translucent
// surfaces do not (a known limit), so that the fog behind it is lit alike.
std::string fogged_sheet(const std::string& variant, const std::string& sheet_material) {
  return R"({ "include": ["graphs/translucency_froxel_fog.json"], "output": { "size": [24, 16] },
  "graph": { "passes": [ { "name": "glass", "variant": ")" + variant + R"(" },
                         { "name": "fog_media", "params": { "near": 0.1, "far": 12, "slices": 64 } } ],
             "outputs": ["glass.color"] },
  "scene": { "camera": { "position": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40 },
    "background": { "radiance": [0.2, 0.3, 0.4] },
    "lights": [ { "type": "directional", "direction": [0, 0, -1], "irradiance": [2, 2, 2] } ],
    "media": { "fog": { "albedo": [0.9, 0.9, 0.9], "extinction": [0.3, 0.3, 0.3] } },
    "materials": { "wall": { "albedo": [0, 0, 0] }, "sheet": )" + sheet_material + R"( },
    "objects": [ { "shape": "plane", "size": [100, 1, 100], "material": "wall", "transform": { "rotate_deg": [90, 0, 0], "translate": [0, 0, -2] } },
                 { "shape": "plane", "size": [100, 1, 100], "material": "sheet", "cast_shadows": false,
                   "transform": { "rotate_deg": [90, 0, 0] } } ] } })";
}

// Against `want` per channel: the largest relative difference of `close` and the smallest
// of `far`.
std::pair<double, double> relative_differences(const Texels& want, const Texels& close, const Texels& far) {
  double worst = 0, gap = 1e30;
  for (uint32_t j = 0; j < kTranslucencyHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucencyWidth; ++i) {
      for (size_t k = 0; k < 3; ++k) {
        const double w = at(want, i, j, k);
        worst = std::max(worst, std::abs(at(close, i, j, k) - w) / w);
        gap = std::min(gap, std::abs(at(far, i, j, k) - w) / w);
      }
    }
  }
  return {worst, gap};
}

TEST_P(Translucency, FogIsAppliedAtTheTranslucentSurfacesOwnDepth) {
  const std::string path = std::string(::volgraph::testing::source_dir()) + "/configs/fogged_sheet.json";
  const Texels translucent = render(fogged_sheet(variant(), R"({ "albedo": [0.8, 0.6, 0.4], "alpha": 1, "alpha_mode": "blend", "ior": 1 })"), path);
  const Texels opaque = render(fogged_sheet(variant(), R"({ "albedo": [0.8, 0.6, 0.4] })"), path);
  const Texels no_sheet = render(fogged_sheet(variant(), R"({ "albedo": [0.8, 0.6, 0.4], "alpha": 0, "alpha_mode": "blend", "ior": 1 })"), path);
  const auto [worst, wall_gap] = relative_differences(opaque, translucent, no_sheet);
  std::printf("fogged sheet: translucent vs opaque %.2e relative at worst; the wall behind differs by %.2f at least\n", worst, wall_gap);
  EXPECT_LT(worst, 2.5e-3);   // five fp16 steps: weighted_oit divides two half-float sums
  EXPECT_GT(wall_gap, 0.05);  // the case can tell the depths apart
}

// The same under a planet's air (configs/graphs/translucency_atmosphere.json): a coverage-1
// sheet 20 km away drawn by the pass is seen through the air in front of it as the same
// opaque sheet is by aerial_perspective_apply, while with the air's volumes unwired from
// the pass (null inputs) it is far off — the air at that distance matters. The camera looks
// up 14° (every ray above the horizon: the air's march ends at the planet's ground).
std::string sheet_under_air(const std::string& variant, const std::string& sheet_material, bool air_wired) {
  const std::string unwire = air_wired ? "" : R"(, "inputs": { "aerial_lookup": null, "aerial_scattering": null, "aerial_transmittance": null })";
  return R"({ "include": ["graphs/translucency_atmosphere.json"], "output": { "size": [24, 16] },
  "graph": { "passes": [ { "name": "glass", "variant": ")" + variant + R"(")" + unwire + R"( } ], "outputs": ["glass.color"] },
  "scene": { "camera": { "position": [0, 10, 0], "target": [0, 10.25, -1], "fov_y_deg": 20, "near": 1, "far": 100000 },
    "atmosphere": { "preset": "earth" },
    "lights": [ { "name": "sun", "type": "directional", "direction": [0, -0.5, -0.8660254], "irradiance": [2, 2, 2] } ],
    "materials": { "sheet": )" + sheet_material + R"( },
    "objects": [ { "shape": "plane", "size": [200000, 1, 200000], "material": "sheet", "cast_shadows": false,
                   "transform": { "rotate_deg": [90, 0, 0], "translate": [0, 10, -20000] } } ] } })";
}

TEST_P(Translucency, AirIsAppliedAtTheTranslucentSurfacesOwnDistance) {
  const std::string path = std::string(::volgraph::testing::source_dir()) + "/configs/sheet_under_air.json";
  const std::string glass = R"({ "albedo": [0.8, 0.6, 0.4], "alpha": 1, "alpha_mode": "blend", "ior": 1 })";
  const Texels translucent = render(sheet_under_air(variant(), glass, true), path);
  const Texels opaque = render(sheet_under_air(variant(), R"({ "albedo": [0.8, 0.6, 0.4] })", true), path);
  const Texels unaired = render(sheet_under_air(variant(), glass, false), path);
  const auto [worst, air_gap] = relative_differences(opaque, translucent, unaired);
  std::printf("sheet under air: translucent vs opaque %.2e relative at worst; without the air %.2f off at least\n", worst, air_gap);
  EXPECT_LT(worst, 2.5e-3);  // five fp16 steps: weighted_oit divides two half-float sums
  EXPECT_GT(air_gap, 0.03);  // the case can tell the air from none (measured 5 % at least)
}

// Screen-space refraction (sorted and depth_peeling, refraction screen_space with refracted_color wired from a
// copy of the scene's colour) of a glass slab turned 35° in front of a wall whose left half
// is bright and right half dark: against the CPU reference's two-interface refraction
// (reference/translucent_rays.cpp, refracted mode), the edge seen through the slab lies
// where the reference sees it (within the pixel its sample straddles) on every row, where
// the straight-through image (refraction none) has it 3 px off; the mean absolute error is
// lower too (what remains: the reference's inner reflections). The slab is wide enough that
// no side face is in view (the slab approximation's case; the scene is the fixture's
// slab_before_edge). At IOR 1 the refracted image is the straight one bit for bit.
TEST_P(Translucency, ScreenSpaceRefractionShiftsWhatIsBehindAsTheSlabDoes) {
  if (variant() == "weighted_oit") GTEST_SKIP() << "screen-space refraction is sorted's and depth_peeling's";
  const Texels refracted = render(slab_before_edge(variant(), "screen_space", 1.5));
  const Scene scene = scene_;
  const Texels straight = render(slab_before_edge(variant(), "none", 1.5));
  reference::IntegrationSettings settings;
  settings.translucency = reference::TranslucencyMode::refracted;
  const reference::ReferenceImage truth = reference::render_image(reference::Renderer(scene, settings), {refracted.width, refracted.height});
  // The edge on each row: the first column from the left whose red falls below 0.5 (the
  // bright side passes about 0.93, the dark about 0.1).
  const auto edge = [](const std::function<double(uint32_t)>& red, uint32_t width) {
    for (uint32_t i = 0; i < width; ++i) {
      if (red(i) < 0.5) return int(i);
    }
    return int(width);
  };
  double refracted_error = 0, straight_error = 0;
  int worst_refracted = 0, least_straight = 1 << 20;
  for (uint32_t j = 0; j < refracted.height; ++j) {
    for (uint32_t i = 0; i < refracted.width; ++i) {
      for (size_t k = 0; k < 3; ++k) {
        refracted_error += std::abs(at(refracted, i, j, k) - truth.at(i, j)[k]);
        straight_error += std::abs(at(straight, i, j, k) - truth.at(i, j)[k]);
      }
    }
    const int want = edge([&](uint32_t i) { return truth.at(i, j)[0]; }, truth.width);
    worst_refracted = std::max(worst_refracted, std::abs(edge([&](uint32_t i) { return at(refracted, i, j, 0); }, refracted.width) - want));
    least_straight = std::min(least_straight, std::abs(edge([&](uint32_t i) { return at(straight, i, j, 0); }, straight.width) - want));
  }
  const double n = 3.0 * refracted.width * refracted.height;
  std::printf("slab before an edge against the refracted reference: the edge off by %d px at worst (none: %d px at least); "
              "mean abs error screen_space %.4f, none %.4f\n",
              worst_refracted, least_straight, refracted_error / n, straight_error / n);
  EXPECT_LE(worst_refracted, 1);   // the pixel the edge's sample straddles
  EXPECT_GE(least_straight, 3);    // the slab's shift, 0.5 sin(35° − 22.5°)/cos 22.5° = 0.117 m, is 3 px here
  EXPECT_LT(refracted_error, straight_error);
  const Texels index_one = render(slab_before_edge(variant(), "screen_space", 1.0));
  const Texels index_one_straight = render(slab_before_edge(variant(), "none", 1.0));
  for (size_t p = 0; p < index_one.rgba.size(); ++p) ASSERT_EQ(index_one.rgba[p], index_one_straight.rgba[p]) << "float " << p;
}

// Khronos' AttenuationTest (../shared/assets/gltf, CC BY 4.0) rendered face-on as
// configs/demo_attenuation_test.json frames it (no shadow map; straight behind: no
// refraction): inside each solid cube of rows R2 (thicknessFactor), R4 (node scale) and R5
// (attenuationDistance), away from its edges, the render must equal the layer over the
// backdrop the pass reads (`behind`, a copy of the colour before it: the backdrop has grid
// lines), with the answer key's colour as the path's transmittance:
//   F L_env + (1 − F) ρ T_key^(1/cos θt) L_behind,
// F Schlick's at the pixel's angle (physics::interface_reflectance), T_key^(1/cos θt) the
// key's colour along the refracted path through the cube's thickness (1.3e-3 off T_key at
// most here). The answer key row R1 itself, thin-walled cubes tinted by their base colour,
// must show F L_env + (1 − F) ρ L_behind (one interface, no path). R3 (thicknessFactor 2 ×
// a thickness texture holding each cube's edge) must show its column's key as R2 does. Metric: |render − prediction| / prediction per channel, at most 3e-3 (fp16
// steps and the slab approximation; measured 1.3e-3 at worst on lavapipe, every variant);
// the prediction × the old exit-interface factor (0.960×) is 3.9e-2 off: fails.
std::string attenuation_test(const std::string& variant) {
  return R"({ "output": { "size": [1280, 720] },
  "scene": { "camera": { "position": [1.25, 0, 40], "target": [1.25, 0, 0], "fov_y_deg": 30 },
             "background": { "radiance": [0.6, 0.6, 0.6] },
             "objects": [ { "shape": "gltf", "file": ")" + std::string(source_dir()) + R"(/../shared/assets/gltf/AttenuationTest/AttenuationTest.glb" } ],
             "lights": [ { "type": "directional", "direction": [0.2, -0.3, -1], "irradiance": [2.5, 2.5, 2.5] } ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "behind", "type": "copy", "inputs": { "source": "lit.color" } },
    { "name": "glass", "type": "translucency", "variant": ")" + variant + R"(", "params": { "refraction": "none" },
      "inputs": { "color": "lit.color", "depth": "lit.depth", "frame": "lit.frame" } } ],
    "outputs": ["glass.color", "behind.copy"] } })";
}

TEST_P(Translucency, AttenuationTestsRowsShowTheirAnswerKey) {
  const std::string text = attenuation_test(variant());
  const LoadedConfig loaded = load_config_text("attenuation.json", text, registry_);
  scene_ = loaded.config.scene;
  Executor executor(device(), loaded.graph, &scene_, {});
  executor.run_frame();
  const Texels image = executor.read_output(0), behind = executor.read_output(1);
  const plumbing::GltfModel model = plumbing::load_gltf(std::string(source_dir()) + "/../shared/assets/gltf/AttenuationTest/AttenuationTest.glb");
  constexpr size_t kAnswerRow = 18;
  const physics::ViewRays rays = physics::view_rays(scene_.camera, double(image.width) / image.height);
  double worst = 0;
  size_t pixels = 0;
  // Checks one cube's front face's middle third (in pixels) against the prediction.
  const auto check_cube = [&](const std::string& what, const Vec3& lo, const Vec3& hi, const plumbing::GltfPrimitive& material,
                              const Vec3& key, bool answer_key) {
    const Vec3 front_lo{lo[0] + (hi[0] - lo[0]) / 3, lo[1] + (hi[1] - lo[1]) / 3, hi[2]};
    const Vec3 front_hi{hi[0] - (hi[0] - lo[0]) / 3, hi[1] - (hi[1] - lo[1]) / 3, hi[2]};
    const physics::ViewUvz a = physics::view_uvz(rays, front_lo), b = physics::view_uvz(rays, front_hi);
    const uint32_t i0 = uint32_t(std::ceil(std::min(a.u, b.u) * image.width)), i1 = uint32_t(std::floor(std::max(a.u, b.u) * image.width));
    const uint32_t j0 = uint32_t(std::ceil(std::min(a.v, b.v) * image.height)), j1 = uint32_t(std::floor(std::max(a.v, b.v) * image.height));
    ASSERT_LT(i0, i1) << what;
    for (uint32_t j = j0; j < j1; ++j) {
      for (uint32_t i = i0; i < i1; ++i) {
        const double cos_i = cos_to_z(i, j, image.width, image.height);
        const double f = physics::interface_reflectance(material.translucency.ior, cos_i);
        const double cos_t = physics::refracted_cosine(material.translucency.ior, cos_i);
        for (size_t k = 0; k < 3; ++k) {
          const double t_path = answer_key ? 1.0 : std::pow(key[k], 1 / cos_t);  // R1: its base colour ρ is the key
          const double want = f * scene_.background[k] + (1 - f) * material.base_color[k] * t_path * at(behind, i, j, k);
          const double error = std::abs(at(image, i, j, k) - want) / want;
          worst = std::max(worst, error);
          EXPECT_LT(error, 3e-3) << what << " pixel " << i << "," << j << " channel " << k << ": " << at(image, i, j, k) << " want " << want;
        }
        ++pixels;
      }
    }
  };
  const auto bounds = [](const plumbing::GltfPrimitive& p, double x_lo, double x_hi) {
    Vec3 lo{1e30, 1e30, 1e30}, hi{-1e30, -1e30, -1e30};
    for (size_t v = 0; v < p.vertices.size(); v += 8) {
      if (p.vertices[v] < x_lo || p.vertices[v] > x_hi) continue;
      for (size_t a = 0; a < 3; ++a) lo[a] = std::min(lo[a], double(p.vertices[v + a])), hi[a] = std::max(hi[a], double(p.vertices[v + a]));
    }
    return std::pair{lo, hi};
  };
  constexpr size_t kThicknessTextureRow = 11;  // R3: one mesh, thicknessFactor 2 × the texture's cube edges
  for (const size_t row : {size_t(0), size_t(6), size_t(12), kAnswerRow}) {  // R2, R4, R5, R1 (the file's node order; R3 is node 11)
    const bool answer_key = row == kAnswerRow;
    for (size_t column = 0; column < 5; ++column) {
      const plumbing::GltfPrimitive& cube = model.primitives.at(row + column);
      ASSERT_EQ(cube.translucency.volume, answer_key ? VolumeKind::thin_walled : VolumeKind::solid);
      const auto [lo, hi] = bounds(cube, -1e30, 1e30);
      check_cube("row " + std::to_string(row) + " column " + std::to_string(column), lo, hi, cube,
                 model.primitives.at(kAnswerRow + column).base_color, answer_key);
      if (row != 0) continue;
      // R3's cube of this column: the row mesh's vertices over R2's cube's x range; its
      // thickness from the texture must give the column's key as R2's factor does.
      const plumbing::GltfPrimitive& textured = model.primitives.at(kThicknessTextureRow);
      ASSERT_EQ(textured.translucency.volume, VolumeKind::solid);
      const double margin = 1e-3 * (hi[0] - lo[0]);
      const auto [tlo, thi] = bounds(textured, lo[0] - margin, hi[0] + margin);
      check_cube("thickness-texture row column " + std::to_string(column), tlo, thi, textured,
                 model.primitives.at(kAnswerRow + column).base_color, false);
    }
  }
  std::printf("AttenuationTest (%s): %zu pixels of 20 solid and 5 thin-walled cubes, worst |render - F L_env - (1-F) rho T_key L_behind| / it = %.2e\n",
              variant().c_str(), pixels, worst);
}

INSTANTIATE_TEST_SUITE_P(Backends, Translucency,
                         ::testing::Combine(::testing::ValuesIn(gpu_backends()), ::testing::Values("sorted", "weighted_oit", "depth_peeling")),
                         TranslucencyVariantFixture::case_name);

}  // namespace
}  // namespace volgraph::testing
