// glTF's alphaMode, KHR_materials_transmission, _ior and _volume as scene.h's Translucency.
// AttenuationTest (Khronos sample, ../shared/assets/gltf) is an answer key: its top row's
// base colours are the colours KHR_materials_volume's attenuation gives each column, so
// every other row's transmittance through its thickness must equal them.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "passes/plumbing/gltf.h"
#include "physics/translucency.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

using plumbing::GltfModel;
using plumbing::GltfPrimitive;
using plumbing::load_gltf;

const std::string kAssets = std::string(::volgraph::testing::source_dir()) + "/../shared/assets/gltf/";

// The transmittance across the primitive's thickness: exp(−σt·d), σt by RTR4 eq. 14.23.
Vec3 transmittance_through(const Translucency& t) {
  Vec3 out;
  for (size_t i = 0; i < 3; ++i) {
    out[i] = std::exp(-physics::sigma_t_from_color(t.attenuation_color[i], t.attenuation_distance) * t.thickness);
  }
  return out;
}

// The primitive's extent along x (the cubes face the viewer along z; their edges are equal).
double x_extent(const GltfPrimitive& p) {
  double lo = 1e30, hi = -1e30;
  for (size_t v = 0; v < p.vertices.size(); v += 8) {
    lo = std::min(lo, double(p.vertices[v]));
    hi = std::max(hi, double(p.vertices[v]));
  }
  return hi - lo;
}

// A one-triangle glTF written to the test's temporary folder: `material` is the JSON of
// its one material, `required` the JSON array of extensionsRequired (and Used).
std::string write_triangle_gltf(const std::string& name, const std::string& material, const std::string& required) {
  const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / (name + ".gltf");
  std::ofstream(path) << R"({ "asset": { "version": "2.0" }, "extensionsUsed": )" << required
                      << R"(, "extensionsRequired": )" << required << R"(,
    "buffers": [ { "byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA" } ],
    "bufferViews": [ { "buffer": 0, "byteLength": 36 } ],
    "accessors": [ { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0] } ],
    "materials": [ )" << material << R"( ],
    "meshes": [ { "primitives": [ { "attributes": { "POSITION": 0 }, "material": 0 } ] } ],
    "nodes": [ { "mesh": 0 } ], "scenes": [ { "nodes": [0] } ], "scene": 0 })";
  return path.string();
}

// The message load_gltf refuses the file with ("" when it loads).
std::string refusal(const std::string& path) {
  try {
    load_gltf(path);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

constexpr const char* kGlassMaterial = R"({ "pbrMetallicRoughness": { "baseColorFactor": [1, 1, 1, 1] },
  "extensions": { "KHR_materials_transmission": { "transmissionFactor": 1 }, "KHR_materials_ior": { "ior": 1.4 },
                  "KHR_materials_dispersion": { "dispersion": 0.75 }, "KHR_materials_volume": { "thicknessFactor": 0.5 } } })";

// glTF 2.0 §3.12: a loader refuses a file only for required extensions it does not
// support; volgraph draws transmission, ior and volume.
TEST(GltfTranslucency, RequiredTranslucencyExtensionsAreAccepted) {
  const std::string path = write_triangle_gltf(
      "required_translucency", kGlassMaterial, R"(["KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_ior", "KHR_materials_dispersion"])");
  ASSERT_EQ(refusal(path), "");
  const GltfModel m = load_gltf(path);
  ASSERT_EQ(m.primitives.size(), 1u);
  EXPECT_EQ(m.primitives[0].translucency.transmission, 1);
  EXPECT_EQ(m.primitives[0].translucency.ior, 1.4);
  EXPECT_EQ(m.primitives[0].translucency.dispersion, 0.75);  // KHR_materials_dispersion, drawn (not listed as ignored)
  EXPECT_TRUE(m.ignored.empty()) << m.ignored.front();
  EXPECT_EQ(m.primitives[0].translucency.volume, VolumeKind::solid);
  // One it does not draw is still refused, by name.
  const std::string other = write_triangle_gltf("required_other", kGlassMaterial, R"(["KHR_materials_transmission", "KHR_texture_basisu"])");
  EXPECT_NE(refusal(other).find("KHR_texture_basisu"), std::string::npos) << refusal(other);
}

// Bad input is refused with one message naming the material and what was expected
// (../shared/DESIGN.md): a base colour outside [0, 1] (glTF 2.0's schema) would be
// negative or amplifying reflectance, an emission above 65504 overflows the half-float colour.
TEST(GltfTranslucency, OutOfRangeColoursAreRefusedNamingTheMaterial) {
  const std::string negative = write_triangle_gltf("negative_base", R"({ "pbrMetallicRoughness": { "baseColorFactor": [-0.5, 1, 1, 1] } })", "[]");
  const std::string bright = write_triangle_gltf("bright_base", R"({ "pbrMetallicRoughness": { "baseColorFactor": [1, 2, 1, 1] } })", "[]");
  const std::string hot = write_triangle_gltf("hot_emission", R"({ "emissiveFactor": [1e9, 0, 0] })", "[]");
  const std::string negative_emission = write_triangle_gltf("negative_emission", R"({ "emissiveFactor": [0, -1, 0] })", "[]");
  for (const std::string& path : {negative, bright}) {
    const std::string message = refusal(path);
    EXPECT_NE(message.find("material 0"), std::string::npos) << message;
    EXPECT_NE(message.find("baseColorFactor"), std::string::npos) << message;
    EXPECT_NE(message.find("[0, 1]"), std::string::npos) << message;
  }
  for (const std::string& path : {hot, negative_emission}) {
    const std::string message = refusal(path);
    EXPECT_NE(message.find("material 0"), std::string::npos) << message;
    EXPECT_NE(message.find("emissiveFactor"), std::string::npos) << message;
    EXPECT_NE(message.find("65504"), std::string::npos) << message;
  }
  // At the limits: loaded.
  EXPECT_EQ(refusal(write_triangle_gltf("limits", R"({ "pbrMetallicRoughness": { "baseColorFactor": [0, 1, 1, 1] }, "emissiveFactor": [65504, 0, 1] })", "[]")), "");
  // Through a config: the scene's check names the file (exit 2 from `volgraph validate`).
  PassRegistry registry;
  register_builtin_passes(registry);
  const std::string text = R"({ "output": { "size": [16, 16] },
    "scene": { "camera": { "position": [0, 0.3, 1], "target": [0, 0.1, 0] },
      "objects": [ { "shape": "gltf", "file": ")" + negative + R"(" } ],
      "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1] } ] },
    "graph": { "passes": [ { "name": "s", "type": "scene" } ], "outputs": ["s.color"] } })";
  std::string diagnostics;
  try {
    load_config_text("a.json", text, registry);
  } catch (const ConfigError& e) {
    diagnostics = e.what();
  }
  EXPECT_NE(diagnostics.find(negative + ": material 0"), std::string::npos) << diagnostics;
}

// The file's nodes in order (one primitive each): the rows R2 (thicknessFactor = edge),
// the labels, R4 (a unit cube scaled by its node), R3 (one mesh with a thickness texture),
// R5 (unit cubes, attenuationDistance = 1 / the column's thickness), the grid, R1 (the key).
constexpr size_t kThicknessRow = 0, kNodeScaleRow = 6, kDistanceRow = 12, kAnswerRow = 18;
constexpr double kColumnThickness[5] = {1.0, 1.5, 2.0, 0.5, 0.25};

TEST(GltfTranslucency, AttenuationTestsRowsMatchItsAnswerKey) {
  const GltfModel m = load_gltf(kAssets + "AttenuationTest/AttenuationTest.glb");
  ASSERT_EQ(m.primitives.size(), 23u);
  for (size_t column = 0; column < 5; ++column) {
    const GltfPrimitive& key = m.primitives[kAnswerRow + column];
    EXPECT_EQ(key.translucency.transmission, 1);
    EXPECT_EQ(key.translucency.volume, VolumeKind::thin_walled);  // the key has no volume: its colour is the answer
    for (size_t row : {kThicknessRow, kNodeScaleRow, kDistanceRow}) {
      const GltfPrimitive& p = m.primitives[row + column];
      EXPECT_EQ(p.translucency.volume, VolumeKind::solid) << "row " << row << " column " << column;
      const Vec3 t = transmittance_through(p.translucency);
      for (size_t i = 0; i < 3; ++i) {
        // The key's colours are printed to 10 digits; double rounding of exp/ln adds ~1e-15.
        EXPECT_NEAR(t[i], key.base_color[i], 1e-9) << "row " << row << " column " << column << " channel " << i;
      }
    }
    // The thickness is the cube's edge in the model's space: node scale applied (R4).
    const GltfPrimitive& scaled = m.primitives[kNodeScaleRow + column];
    EXPECT_NEAR(scaled.translucency.thickness, kColumnThickness[column], 1e-12);
    EXPECT_NEAR(x_extent(scaled), scaled.translucency.thickness, 1e-5);
    EXPECT_NEAR(x_extent(m.primitives[kThicknessRow + column]), m.primitives[kThicknessRow + column].translucency.thickness, 1e-5);
  }
  // The labels and the backdrop are opaque.
  EXPECT_FALSE(m.primitives[5].translucency.translucent());
  EXPECT_FALSE(m.primitives[17].translucency.translucent());
  EXPECT_TRUE(m.primitives[11].thickness_texture);  // R3's texture is loaded (sampled by the translucency passes)
}

TEST(GltfTranslucency, TheVasesMaterialsKeepTheirModes) {
  const GltfModel m = load_gltf(kAssets + "GlassVaseFlowers/GlassVaseFlowers.glb");
  int mask = 0, blend = 0, transmitting = 0;
  for (const GltfPrimitive& p : m.primitives) {
    const Translucency& t = p.translucency;
    if (t.alpha_mode == AlphaMode::mask) {
      ++mask;
      EXPECT_EQ(t.alpha_cutoff, 0.5);  // the file's default
      EXPECT_FALSE(t.translucent());
    }
    if (t.alpha_mode == AlphaMode::blend) {
      ++blend;
      EXPECT_NEAR(t.alpha, 0.3, 1e-12);  // GlassAlpha's baseColorFactor alpha
      EXPECT_TRUE(t.translucent());
    }
    if (t.transmission > 0) {
      ++transmitting;
      EXPECT_EQ(t.volume, VolumeKind::solid);
      EXPECT_GT(t.thickness, 0);
      EXPECT_EQ(t.attenuation_distance, 1e30);  // no attenuation given: clear glass
      EXPECT_EQ(t.ior, 1.5);                    // no KHR_materials_ior: glTF's default
    }
  }
  EXPECT_GT(mask, 0);
  EXPECT_GT(blend, 0);
  EXPECT_GT(transmitting, 0);
}

// The registry's annotator marks a glTF object whose file has translucent primitives, so
// the scene has the feature the translucency pass needs; an opaque model is not marked.
TEST(GltfTranslucency, TheAnnotatorMarksObjectsWithTranslucentMaterials) {
  PassRegistry registry;
  register_builtin_passes(registry);
  auto scene_of = [&](const std::string& file) {
    const std::string text = R"({ "output": { "size": [16, 16] },
      "scene": { "camera": { "position": [0, 0.3, 1], "target": [0, 0.1, 0] },
        "objects": [ { "shape": "gltf", "file": ")" + kAssets + file + R"(" } ],
        "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1] } ] },
      "graph": { "passes": [ { "name": "c", "type": "clear" } ], "outputs": ["c.target"] } })";
    return load_config_text("a.json", text, registry).config.scene;
  };
  const Scene vase = scene_of("GlassVaseFlowers/GlassVaseFlowers.glb");
  EXPECT_TRUE(vase.objects.at(0).translucent_in_file);
  EXPECT_TRUE(vase.features() & feature_bit(SceneFeature::translucent_objects));
  const Scene suzanne = scene_of("Suzanne/Suzanne.gltf");
  EXPECT_FALSE(suzanne.objects.at(0).translucent_in_file);
  EXPECT_FALSE(suzanne.features() & feature_bit(SceneFeature::translucent_objects));
}

}  // namespace
}  // namespace volgraph
