// Media in the scene config: the three ways to give σ (σs/σa; albedo + extinction;
// albedo + a transmittance colour through a distance, eq. 14.23, colour 0 included),
// local volumes' size and procedural noise, and one clear error for each misuse.
#include <cmath>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "physics/media.h"

namespace volgraph {
namespace {

std::string config_with_media(const std::string& media) {
  return R"({
  "output": { "size": [32, 16] },
  "scene": {
    "camera": { "position": [0, 1, 5], "target": [0, 0, 0] },
    "media": )" + media + R"(
  },
  "graph": { "passes": [ { "name": "c", "type": "clear" } ], "outputs": ["c.target"] }
})";
}

class MediaConfig : public ::testing::Test {
 protected:
  MediaConfig() { register_builtin_passes(registry_); }
  Scene scene(const std::string& media) { return load_config_text("m.json", config_with_media(media), registry_).config.scene; }
  std::string error(const std::string& media) {
    try {
      scene(media);
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.diagnostics().size(), 1u);
      return e.diagnostics().front().where.pointer + ": " + e.diagnostics().front().message;
    }
    ADD_FAILURE() << "expected an error for " << media;
    return "";
  }
  PassRegistry registry_;
};

TEST_F(MediaConfig, TransmittanceColourGivesSigmaThroughItsDistance) {
  const Scene s = scene(R"({ "fog": { "albedo": [0.8, 0.8, 0.8], "transmittance": { "color": [0.5, 0.25, 1], "distance": 10 } } })");
  ASSERT_TRUE(s.media.fog);
  const double sigma_t[3] = {std::log(2.0) / 10, std::log(4.0) / 10, 0.0};
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(s.media.fog->sigma_s[c], 0.8 * sigma_t[c], 1e-15);
    EXPECT_NEAR(s.media.fog->sigma_a[c], 0.2 * sigma_t[c], 1e-15);
  }
}

TEST_F(MediaConfig, ATransmittanceColourOfZeroIsAsOpaqueAsAllowed) {
  const Scene s = scene(R"({ "fog": { "albedo": [1, 1, 1], "transmittance": { "color": [0, 0, 0], "distance": 2 } } })");
  EXPECT_DOUBLE_EQ(s.media.fog->sigma_s[0], -std::log(physics::kMinTransmittance<double>) / 2);
  EXPECT_TRUE(std::isfinite(s.media.fog->sigma_s[0]));
}

TEST_F(MediaConfig, AlbedoAndExtinction) {
  const Scene s = scene(R"({ "fog": { "albedo": [0.5, 1, 0], "extinction": [2, 2, 2], "g": 0.6 } })");
  EXPECT_EQ(s.media.fog->sigma_s, (Vec3{1, 2, 0}));
  EXPECT_EQ(s.media.fog->sigma_a, (Vec3{1, 0, 2}));
  EXPECT_EQ(s.media.fog->g, 0.6);
}

TEST_F(MediaConfig, VolumesHaveASizeAndNoise) {
  const Scene s = scene(R"({ "volumes": [ { "shape": "ellipsoid", "size": [2, 1, 3], "sigma_s": [1, 1, 1],
                                            "noise": { "octaves": 4, "scale": 0.5, "coverage": 0.6, "edge_fade": 0.2 } } ] })");
  ASSERT_EQ(s.media.volumes.size(), 1u);
  EXPECT_EQ(s.media.volumes[0].shape, Shape::ellipsoid);
  EXPECT_EQ(s.media.volumes[0].size, (Vec3{2, 1, 3}));
  EXPECT_EQ(s.media.volumes[0].noise.octaves, 4);
  EXPECT_EQ(s.media.volumes[0].noise.scale, 0.5);
  EXPECT_EQ(s.media.volumes[0].noise.coverage, 0.6);
  EXPECT_EQ(s.media.volumes[0].noise.edge_fade, 0.2);
  EXPECT_TRUE(s.features() & feature_bit(SceneFeature::local_volumes));
}

TEST_F(MediaConfig, EachMisuseGetsOneClearError) {
  EXPECT_NE(error(R"({ "fog": { "sigma_s": [1, 1, 1], "extinction": [1, 1, 1] } })").find("give one of"), std::string::npos);
  EXPECT_NE(error(R"({ "fog": { "extinction": [1, 1, 1], "transmittance": { "color": [0.5, 0.5, 0.5] } } })").find("give one of"),
            std::string::npos);
  EXPECT_NE(error(R"({ "fog": { "albedo": [1, 1, 1] } })").find("albedo needs extinction or transmittance"), std::string::npos);
  EXPECT_NE(error(R"({ "fog": { "albedo": [1, 1, 1], "transmittance": { "color": [0.5, 0.5, 0.5], "distance": 0 } } })")
                .find("/scene/media/fog/transmittance/distance"),
            std::string::npos);
  EXPECT_NE(error(R"({ "volumes": [ { "sigma_s": [1, 1, 1], "noise": { "octaves": 9 } } ] })").find("/scene/media/volumes/0/noise/octaves"),
            std::string::npos);
  EXPECT_NE(error(R"({ "fog": { "transmittance": { "colour": [0.5, 0.5, 0.5] } } })").find("did you mean"), std::string::npos);
}

TEST_F(MediaConfig, NoiseParametersAreCheckedWhereTheyAre) {
  auto noise_error = [&](const std::string& noise) {
    return error(R"({ "volumes": [ { "sigma_s": [1, 1, 1], "noise": )" + noise + " } ] }");
  };
  EXPECT_NE(noise_error(R"({ "octaves": 0 })").find("/scene/media/volumes/0/noise/octaves: expected an integer in [1, 8], got 0"),
            std::string::npos);
  EXPECT_NE(noise_error(R"({ "octaves": 2.5 })").find("/scene/media/volumes/0/noise/octaves"), std::string::npos);
  EXPECT_NE(noise_error(R"({ "octaves": 3, "scale": 0 })").find("/scene/media/volumes/0/noise/scale: expected a number in"),
            std::string::npos);
  EXPECT_NE(noise_error(R"({ "octaves": 3, "coverage": 0 })").find("/scene/media/volumes/0/noise/coverage"), std::string::npos);
  EXPECT_NE(noise_error(R"({ "octaves": 3, "coverage": 1.5 })").find("/scene/media/volumes/0/noise/coverage"), std::string::npos);
  EXPECT_NE(noise_error(R"({ "scale": 2 })").find("/scene/media/volumes/0/noise/scale: \"scale\" needs \"octaves\""),
            std::string::npos);
  const Scene faded = scene(R"({ "volumes": [ { "sigma_s": [1, 1, 1], "noise": { "edge_fade": 0.3 } } ] })");
  EXPECT_EQ(faded.media.volumes[0].noise.octaves, 0) << "an edge fade alone: no noise";
}

}  // namespace
}  // namespace volgraph
