// A material's translucency in a config: each key lands in scene.h's Translucency, an
// alpha below 1 blends unless alpha_mode says otherwise, a shell needs its thickness,
// one clear error for each bad value, and the scene feature the translucency pass keys on.
#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "passes/passes.h"

namespace volgraph {
namespace {

constexpr SceneFeatures kTranslucent = feature_bit(SceneFeature::translucent_objects);

std::string config_with_material(const std::string& material) {
  return R"({
  "output": { "size": [16, 16] },
  "scene": {
    "camera": { "position": [0, 1, 5], "target": [0, 0, 0] },
    "lights": [ { "name": "sun", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1] } ],
    "materials": { "glass": )" + material + R"( },
    "objects": [ { "name": "pane", "shape": "box", "material": "glass" } ]
  },
  "graph": { "passes": [ { "name": "c", "type": "clear" } ], "outputs": ["c.target"] }
})";
}

class TranslucencyConfig : public ::testing::Test {
 protected:
  TranslucencyConfig() { register_builtin_passes(registry_); }
  Scene scene(const std::string& material) {
    return load_config_text("a.json", config_with_material(material), registry_).config.scene;
  }
  Translucency translucency(const std::string& material) {
    const Scene s = scene(material);
    EXPECT_EQ(s.materials.size(), 1u);
    return s.materials.empty() ? Translucency{} : s.materials.front().translucency;
  }
  // "pointer: message" of the one diagnostic the material gives.
  std::string error(const std::string& material) {
    try {
      scene(material);
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.diagnostics().size(), 1u) << e.what();
      return e.diagnostics().front().where.pointer + ": " + e.diagnostics().front().message;
    }
    ADD_FAILURE() << "expected an error for " << material;
    return "";
  }
  PassRegistry registry_;
};

TEST_F(TranslucencyConfig, AMaterialWithoutTheKeysIsOpaqueWithScenesDefaults) {
  const Translucency t = translucency(R"({ "albedo": [0.5, 0.5, 0.5] })");
  const Translucency d;
  EXPECT_EQ(t.alpha, d.alpha);
  EXPECT_EQ(t.alpha_mode, AlphaMode::opaque);
  EXPECT_EQ(t.alpha_cutoff, d.alpha_cutoff);
  EXPECT_EQ(t.transmission, 0);
  EXPECT_EQ(t.ior, 1.5);
  EXPECT_EQ(t.dispersion, 0);
  EXPECT_EQ(t.attenuation_distance, d.attenuation_distance);
  EXPECT_EQ(t.volume, VolumeKind::thin_walled);
  EXPECT_FALSE(t.translucent());
  EXPECT_FALSE(scene(R"({ "albedo": [0.5, 0.5, 0.5] })").features() & kTranslucent);
}

TEST_F(TranslucencyConfig, EveryKeyLandsInTheMaterial) {
  const Translucency t = translucency(R"({ "alpha": 0.75, "alpha_mode": "mask", "alpha_cutoff": 0.25,
    "transmission": 0.9, "ior": 1.33, "dispersion": 0.5, "attenuation_color": [0.5, 0.25, 0], "attenuation_distance": 2,
    "volume": "shell", "thickness": 0.01 })");
  EXPECT_EQ(t.alpha, 0.75);
  EXPECT_EQ(t.alpha_mode, AlphaMode::mask);  // named: it wins over the alpha's blend
  EXPECT_EQ(t.alpha_cutoff, 0.25);
  EXPECT_EQ(t.transmission, 0.9);
  EXPECT_EQ(t.ior, 1.33);
  EXPECT_EQ(t.dispersion, 0.5);
  EXPECT_EQ(t.attenuation_color, (Vec3{0.5, 0.25, 0}));
  EXPECT_EQ(t.attenuation_distance, 2);
  EXPECT_EQ(t.volume, VolumeKind::shell);
  EXPECT_EQ(t.thickness, 0.01);
  EXPECT_TRUE(t.translucent());
}

TEST_F(TranslucencyConfig, AnAlphaBelowOneBlendsUnlessTheModeIsNamed) {
  EXPECT_EQ(translucency(R"({ "alpha": 0.5 })").alpha_mode, AlphaMode::blend);
  EXPECT_EQ(translucency(R"({ "alpha": 1 })").alpha_mode, AlphaMode::opaque);
  EXPECT_EQ(translucency(R"({ "alpha": 0.5, "alpha_mode": "opaque" })").alpha_mode, AlphaMode::opaque);
  EXPECT_TRUE(scene(R"({ "alpha": 0.5 })").features() & kTranslucent);
  // Mask cuts holes; what is left is opaque: drawn by the scene, not the translucency pass.
  EXPECT_FALSE(scene(R"({ "alpha": 0.5, "alpha_mode": "mask" })").features() & kTranslucent);
}

TEST_F(TranslucencyConfig, TransmissionMakesTheObjectTranslucentAndChangesTheSceneHash) {
  const Scene glass = scene(R"({ "transmission": 1 })");
  const Scene other = scene(R"({ "transmission": 1, "attenuation_color": [0.5, 0.5, 0.5], "attenuation_distance": 1 })");
  EXPECT_TRUE(glass.features() & kTranslucent);
  EXPECT_NE(glass.hash(part_bit(ScenePart::geometry)), other.hash(part_bit(ScenePart::geometry)));
}

TEST_F(TranslucencyConfig, BadValuesGetOneClearMessage) {
  EXPECT_EQ(error(R"({ "alpha_mode": "cutout" })"),
            "/scene/materials/glass/alpha_mode: unknown value \"cutout\"; expected one of opaque, mask, blend");
  EXPECT_EQ(error(R"({ "volume": "soild" })"),
            "/scene/materials/glass/volume: unknown value \"soild\" (did you mean \"solid\"?); expected one of thin_walled, shell, solid");
  EXPECT_EQ(error(R"({ "transmission": 1, "volume": "shell" })"),
            "/scene/materials/glass/volume: a shell needs its wall's thickness; expected \"thickness\" > 0 m beside \"volume\": \"shell\"");
  EXPECT_NE(error(R"({ "ior": 0.5 })").find("/scene/materials/glass/ior: "), std::string::npos);
  EXPECT_NE(error(R"({ "dispersion": -1 })").find("/scene/materials/glass/dispersion: "), std::string::npos) << error(R"({ "dispersion": -1 })");
  EXPECT_NE(error(R"({ "alpha": 1.5 })").find("/scene/materials/glass/alpha: "), std::string::npos);
  EXPECT_NE(error(R"({ "attenuation_distance": 0 })").find("/scene/materials/glass/attenuation_distance: "), std::string::npos);
  EXPECT_NE(error(R"({ "attenuation_color": [0.5, 2, 0.5] })").find("/scene/materials/glass/attenuation_color"), std::string::npos);
  EXPECT_NE(error(R"({ "thickness": -1 })").find("/scene/materials/glass/thickness: "), std::string::npos);
  // Emission lands in half-float colour: above 65504 it is refused, not clamped silently.
  EXPECT_NE(error(R"({ "emissive": [1e9, 0, 0] })").find("/scene/materials/glass/emissive"), std::string::npos);
  EXPECT_NE(error(R"({ "emissive": [1e9, 0, 0] })").find("65504"), std::string::npos) << error(R"({ "emissive": [1e9, 0, 0] })");
  EXPECT_EQ(translucency(R"({ "emissive": [65504, 0, 0] })").alpha, 1);
  EXPECT_NE(error(R"({ "tranmission": 1 })").find("did you mean \"transmission\""), std::string::npos);
}

}  // namespace
}  // namespace volgraph
