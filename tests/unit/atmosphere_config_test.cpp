// The scene's "atmosphere" in a config: presets (earth exactly scene.h's defaults, mars the
// physics preset), overrides on a preset, "custom", the scale-height shorthand, the sun
// (which directional light, its position from the time of day by NOAA's formulas), one
// clear error for each bad value, the scene feature and the hash part the LUTs key on.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/sun_position.h"

namespace volgraph {
namespace {

constexpr const char* kLights = R"([
      { "name": "sun", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1] },
      { "name": "lamp", "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1] },
      { "name": "moon", "type": "directional", "direction": [0, -1, 1], "irradiance": [0.1, 0.1, 0.1] }
    ])";

std::string config_with_atmosphere(const std::string& atmosphere, const std::string& lights, const std::string& camera) {
  return R"({
  "output": { "size": [32, 16] },
  "scene": {
    "camera": )" + camera + R"(,
    "lights": )" + lights + R"(,
    "atmosphere": )" + atmosphere + R"(
  },
  "graph": { "passes": [ { "name": "c", "type": "clear" } ], "outputs": ["c.target"] }
})";
}

constexpr const char* kCamera = R"({ "position": [0, 1, 5], "target": [0, 0, 0] })";

void expect_same_layer(const DensityLayer& a, const DensityLayer& b, const char* what) {
  EXPECT_EQ(a.width, b.width) << what;
  EXPECT_EQ(a.exp_term, b.exp_term) << what;
  EXPECT_EQ(a.exp_scale, b.exp_scale) << what;
  EXPECT_EQ(a.linear_term, b.linear_term) << what;
  EXPECT_EQ(a.constant_term, b.constant_term) << what;
}

void expect_same_profile(const DensityProfile& a, const DensityProfile& b, const char* what) {
  expect_same_layer(a.lower, b.lower, what);
  expect_same_layer(a.upper, b.upper, what);
}

// Every value of the model, exactly (the sun's light and the Where aside).
void expect_same_atmosphere(const Atmosphere& a, const Atmosphere& b) {
  EXPECT_EQ(a.preset, b.preset);
  EXPECT_EQ(a.bottom_radius, b.bottom_radius);
  EXPECT_EQ(a.top_radius, b.top_radius);
  EXPECT_EQ(a.rayleigh_scattering, b.rayleigh_scattering);
  expect_same_profile(a.rayleigh_density, b.rayleigh_density, "rayleigh_density");
  EXPECT_EQ(a.mie_scattering, b.mie_scattering);
  EXPECT_EQ(a.mie_extinction, b.mie_extinction);
  expect_same_profile(a.mie_density, b.mie_density, "mie_density");
  EXPECT_EQ(a.mie_g, b.mie_g);
  EXPECT_EQ(a.mie_phase, b.mie_phase);
  EXPECT_EQ(a.absorption_extinction, b.absorption_extinction);
  expect_same_profile(a.absorption_density, b.absorption_density, "absorption_density");
  EXPECT_EQ(a.ground_albedo, b.ground_albedo);
  EXPECT_EQ(a.origin_altitude, b.origin_altitude);
  EXPECT_EQ(a.sun_angular_radius, b.sun_angular_radius);
}

class AtmosphereConfig : public ::testing::Test {
 protected:
  AtmosphereConfig() { register_builtin_passes(registry_); }
  Scene scene(const std::string& atmosphere, const std::string& lights = kLights, const std::string& camera = kCamera) {
    return load_config_text("a.json", config_with_atmosphere(atmosphere, lights, camera), registry_).config.scene;
  }
  Atmosphere atmosphere(const std::string& json) {
    const Scene s = scene(json);
    EXPECT_TRUE(s.atmosphere.has_value());
    return s.atmosphere.value_or(Atmosphere{});
  }
  // "pointer: message" of the one diagnostic the atmosphere gives.
  std::string error(const std::string& atmosphere, const std::string& lights = kLights) {
    try {
      scene(atmosphere, lights);
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.diagnostics().size(), 1u) << e.what();
      return e.diagnostics().front().where.pointer + ": " + e.diagnostics().front().message;
    }
    ADD_FAILURE() << "expected an error for " << atmosphere;
    return "";
  }
  PassRegistry registry_;
};

TEST_F(AtmosphereConfig, EarthIsExactlyTheSceneDefaults) {
  expect_same_atmosphere(atmosphere(R"({ "preset": "earth" })"), Atmosphere{});
  expect_same_atmosphere(atmosphere("{}"), Atmosphere{});  // earth when no preset is named
}

TEST_F(AtmosphereConfig, MarsIsThePhysicsPreset) {
  const std::optional<Atmosphere> mars = physics::atmosphere_preset("mars");
  ASSERT_TRUE(mars);
  const Atmosphere a = atmosphere(R"({ "preset": "mars" })");
  expect_same_atmosphere(a, *mars);
  EXPECT_NE(a.bottom_radius, Atmosphere{}.bottom_radius);
}

TEST_F(AtmosphereConfig, KeysOverrideThePresetOneByOne) {
  const Atmosphere a = atmosphere(R"({ "preset": "earth", "bottom_radius": 6000e3, "top_radius": 6100e3,
    "mie_g": 0.7, "mie_phase": "henyey_greenstein", "ground_albedo": [0.1, 0.2, 0.3],
    "absorption_extinction": [0, 0, 0], "origin_altitude": 1500, "sun": { "angular_radius": 0.01 } })");
  Atmosphere expected;
  expected.bottom_radius = 6000e3;
  expected.top_radius = 6100e3;
  expected.mie_g = 0.7;
  expected.mie_phase = MiePhase::henyey_greenstein;
  expected.ground_albedo = {0.1, 0.2, 0.3};
  expected.absorption_extinction = {0, 0, 0};
  expected.origin_altitude = 1500;
  expected.sun_angular_radius = 0.01;
  expect_same_atmosphere(a, expected);
}

TEST_F(AtmosphereConfig, ScaleHeightsAreTheExponentialProfile) {
  const Atmosphere a = atmosphere(R"({ "rayleigh_scale_height": 8000, "mie_scale_height": 500 })");
  expect_same_profile(a.rayleigh_density, Atmosphere{}.rayleigh_density, "8 km is the preset's");
  expect_same_profile(a.mie_density, DensityProfile{{}, {0, 1, -1.0 / 500, 0, 0}}, "mie");
}

TEST_F(AtmosphereConfig, AProfileReplacesThePresetsWithItsLayers) {
  const Atmosphere a = atmosphere(R"({ "absorption_density": {
    "lower": { "width": 20e3, "linear_term": 5e-5, "constant_term": -0.5 },
    "upper": { "exp_term": 2, "exp_scale": -1e-4 } }, "mie_density": { "upper": { "constant_term": 1 } } })");
  expect_same_profile(a.absorption_density, DensityProfile{{20e3, 0, 0, 5e-5, -0.5}, {0, 2, -1e-4, 0, 0}}, "absorption");
  expect_same_profile(a.mie_density, DensityProfile{{}, {0, 0, 0, 0, 1}}, "mie: a layer left out is 0");
}

TEST_F(AtmosphereConfig, CustomStartsFromNoScatteringAndNoAbsorption) {
  const Atmosphere a = atmosphere(R"({ "preset": "custom", "bottom_radius": 1000, "top_radius": 1100,
    "rayleigh_scattering": [1e-3, 2e-3, 4e-3], "rayleigh_scale_height": 10 })");
  EXPECT_EQ(a.preset, "custom");
  EXPECT_EQ(a.bottom_radius, 1000);
  EXPECT_EQ(a.top_radius, 1100);
  EXPECT_EQ(a.rayleigh_scattering, (Vec3{1e-3, 2e-3, 4e-3}));
  expect_same_profile(a.rayleigh_density, DensityProfile{{}, {0, 1, -0.1, 0, 0}}, "rayleigh");
  EXPECT_EQ(a.mie_scattering, (Vec3{0, 0, 0}));
  EXPECT_EQ(a.mie_extinction, (Vec3{0, 0, 0}));
  EXPECT_EQ(a.absorption_extinction, (Vec3{0, 0, 0}));
  expect_same_profile(a.mie_density, DensityProfile{}, "mie");
  expect_same_profile(a.absorption_density, DensityProfile{}, "absorption");
}

TEST_F(AtmosphereConfig, TheSunIsTheFirstDirectionalLightOrTheNamedOne) {
  EXPECT_EQ(atmosphere("{}").sun_light, 0);
  EXPECT_EQ(atmosphere(R"({ "sun": { "light": "moon" } })").sun_light, 2);
  const Scene s = scene("{}", R"([ { "type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1] },
                                   { "type": "directional", "direction": [1, -1, 0], "irradiance": [2, 2, 2] } ])");
  EXPECT_EQ(s.atmosphere->sun_light, 1);
  EXPECT_EQ(s.lights[1].direction, (Vec3{1, -1, 0}));  // no time of day: the light's own direction
}

TEST_F(AtmosphereConfig, TheTimeOfDaySetsTheSunLightsDirection) {
  const Scene s = scene(R"({ "sun": { "light": "moon", "time_of_day": 15.5, "latitude_deg": 48.85, "day_of_year": 172 } })");
  const Vec3 toward = physics::sun_direction(15.5, 48.85, 172);
  for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(s.lights[2].direction[k], -toward[k], 1e-15);  // libm against folded constants
  EXPECT_EQ(s.lights[0].direction, (Vec3{0, -1, 0}));  // the other directional light is untouched
  EXPECT_LT(s.lights[2].direction[1], 0);               // afternoon: the light comes down
  EXPECT_GT(s.lights[2].direction[0], 0);               // from the west, travelling east
}

TEST_F(AtmosphereConfig, ASunBelowTheHorizonIsNight) {
  const Scene s = scene(R"({ "sun": { "time_of_day": 0, "latitude_deg": 45, "day_of_year": 80 } })");
  EXPECT_GT(s.lights[0].direction[1], 0.5);  // midnight: the sun 45° below, its light travels up
}

TEST_F(AtmosphereConfig, AnyCameraPositionIsAccepted) {
  for (const char* camera : {R"({ "position": [0, 1e6, 0], "target": [0, 1e6, 1] })",    // above the top: from space
                             R"({ "position": [0, -50, 0], "target": [0, -50, 1] })",  // below the ground
                             R"({ "position": [0, 0, 0], "target": [1, 0, 0] })"}) {
    EXPECT_TRUE(scene("{}", kLights, camera).atmosphere) << camera;
  }
}

TEST_F(AtmosphereConfig, EachBadValueGetsOneClearError) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({ "bottom_radius": 0 })", "/scene/atmosphere/bottom_radius: expected a number in [1, 1e+09] m, got 0"},
      {R"({ "top_radius": 2e9 })", "/scene/atmosphere/top_radius: expected a number in [1, 1e+09] m, got 2000000000.0"},
      {R"({ "top_radius": 6000e3 })",
       "/scene/atmosphere/top_radius: top_radius (6000000 m) must exceed bottom_radius (6360000 m)"},
      {R"({ "bottom_radius": 6420e3 })",
       "/scene/atmosphere/bottom_radius: top_radius (6420000 m) must exceed bottom_radius (6420000 m)"},
      {R"({ "rayleigh_scattering": [1e-6, -1e-6, 0] })",
       "/scene/atmosphere/rayleigh_scattering/1: expected a number in [0, 1000000], got -1e-06"},
      {R"({ "mie_extinction": [1, 1, "x"] })",
       "/scene/atmosphere/mie_extinction: expected an array of 3 numbers in [0, 1000000], got an array of 3"},
      {R"({ "mie_scattering": [5e-6, 1e-6, 1e-6] })",
       "/scene/atmosphere/mie_scattering: mie_scattering (5e-06 1/m in channel 0) exceeds mie_extinction (4.44e-06); "
       "expected scattering ≤ extinction (extinction = scattering + absorption)"},
      {R"({ "rayleigh_density": { "upper": { "exp_term": 1, "exp_scale": 0.001 } } })",
       "/scene/atmosphere/rayleigh_density/upper/exp_scale: exp_scale is 0.001 1/m; expected at most 0 (a layer's "
       "exponential may only decay with altitude)"},
      {R"({ "mie_density": { "upper": { "width": 10, "exp_term": 1 } } })",
       "/scene/atmosphere/mie_density/upper/width: the upper layer reaches the top of the atmosphere: it has no \"width\""},
      {R"({ "absorption_density": { "lower": { "width": -1 } } })",
       "/scene/atmosphere/absorption_density/lower/width: expected a number in [0, 1e+09], got -1"},
      {R"({ "absorption_density": { "lower": { "linear_term": true } } })",
       "/scene/atmosphere/absorption_density/lower/linear_term: expected a number in [-1e+09, 1e+09], got true"},
      {R"({ "rayleigh_density": { "middle": {} } })",
       "/scene/atmosphere/rayleigh_density/middle: unknown key \"middle\"; expected one of lower, upper"},
      {R"({ "mie_density": { "upper": { "exp_scal": -1 } } })",
       "/scene/atmosphere/mie_density/upper/exp_scal: unknown key \"exp_scal\" (did you mean \"exp_scale\"?); expected one of "
       "width, exp_term, exp_scale, linear_term, constant_term"},
      {R"({ "rayleigh_scale_height": 0 })",
       "/scene/atmosphere/rayleigh_scale_height: expected a number in [0.001, 1e+09] m, got 0"},
      {R"({ "mie_scale_height": 1200, "mie_density": { "upper": { "exp_term": 1 } } })",
       "/scene/atmosphere/mie_scale_height: give one of \"mie_density\" or \"mie_scale_height\""},
      {R"({ "mie_g": 1 })", "/scene/atmosphere/mie_g: expected a number in [-0.999, 0.999], got 1"},
      {R"({ "mie_phase": "henyey" })",
       "/scene/atmosphere/mie_phase: unknown value \"henyey\"; expected one of henyey_greenstein, cornette_shanks"},
      {R"({ "ground_albedo": [0.5, 1.5, 0.5] })", "/scene/atmosphere/ground_albedo/1: expected a number in [0, 1], got 1.5"},
      {R"({ "origin_altitude": -1 })", "/scene/atmosphere/origin_altitude: expected a number in [0, 1e+09] m, got -1"},
      {R"({ "origin_altitude": 60000 })",
       "/scene/atmosphere/origin_altitude: origin_altitude (60000 m) must be below the top of the atmosphere "
       "(top_radius − bottom_radius = 60000 m)"},
      {R"({ "raleigh_scattering": [0, 0, 0] })",
       "/scene/atmosphere/raleigh_scattering: unknown key \"raleigh_scattering\" (did you mean \"rayleigh_scattering\"?); "
       "expected one of preset, bottom_radius, top_radius, rayleigh_scattering, rayleigh_density, rayleigh_scale_height, "
       "mie_scattering, mie_extinction, mie_density, mie_scale_height, mie_g, mie_phase, absorption_extinction, "
       "absorption_density, ground_albedo, origin_altitude, sun"},
      {R"({ "preset": "mras" })",
       "/scene/atmosphere/preset: unknown preset \"mras\" (did you mean \"mars\"?); expected one of earth, mars, custom"},
      {R"({ "preset": "custom", "top_radius": 1100 })",
       "/scene/atmosphere: a \"custom\" atmosphere needs \"bottom_radius\" (it starts from no preset)"},
      {R"({ "preset": "custom", "bottom_radius": 1000, "top_radius": 1100, "mie_extinction": [1e-3, 1e-3, 1e-3] })",
       "/scene/atmosphere/mie_extinction: \"mie_extinction\" needs \"mie_density\" or \"mie_scale_height\" beside it: a "
       "custom atmosphere's densities start at 0"},
      {R"({ "sun": { "light": "lamp" } })",
       "/scene/atmosphere/sun/light: the light \"lamp\" is a point light; the atmosphere's sun must be a directional light"},
      {R"({ "sun": { "light": "sunn" } })",
       "/scene/atmosphere/sun/light: unknown light \"sunn\" (did you mean \"sun\"?); expected one of sun, lamp, moon"},
      {R"({ "sun": { "angular_radius": 0 } })", "/scene/atmosphere/sun/angular_radius: expected a number in (0, 0.5] rad, got 0"},
      {R"({ "sun": { "angular_radius": 0.6 } })",
       "/scene/atmosphere/sun/angular_radius: expected a number in (0, 0.5] rad, got 0.6"},
      {R"({ "sun": { "time_of_day": 24, "latitude_deg": 0, "day_of_year": 80 } })",
       "/scene/atmosphere/sun/time_of_day: expected a number in [0, 24) h, got 24"},
      {R"({ "sun": { "time_of_day": 12, "latitude_deg": -90.5, "day_of_year": 80 } })",
       "/scene/atmosphere/sun/latitude_deg: expected a number in [-90, 90]°, got -90.5"},
      {R"({ "sun": { "time_of_day": 12, "latitude_deg": 10, "day_of_year": 367 } })",
       "/scene/atmosphere/sun/day_of_year: expected an integer in [1, 366], got 367"},
      {R"({ "sun": { "time_of_day": 12 } })",
       "/scene/atmosphere/sun: the sun's \"time_of_day\" needs \"latitude_deg\", \"day_of_year\" beside it: time_of_day, "
       "latitude_deg and day_of_year set the sun light's direction together"},
      {R"({ "sun": { "hour": 12 } })",
       "/scene/atmosphere/sun/hour: unknown key \"hour\"; expected one of light, angular_radius, time_of_day, latitude_deg, "
       "day_of_year"},
      {R"("earth")", "/scene/atmosphere: expected an object, got the string \"earth\""},
  };
  for (const auto& [json, message] : cases) EXPECT_EQ(error(json), message) << json;
}

TEST_F(AtmosphereConfig, ASceneWithoutADirectionalLightHasNoSun) {
  EXPECT_EQ(error("{}", R"([ { "type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1] } ])"),
            "/scene/atmosphere: the atmosphere's sun is the scene's first directional light, and the scene has none; "
            "expected a directional light in \"lights\" (or \"sun\": {\"light\": NAME})");
}

TEST_F(AtmosphereConfig, TheFeatureIsSetOnlyWithAnAtmosphere) {
  Scene s = scene("{}");
  EXPECT_TRUE(s.features() & feature_bit(SceneFeature::atmosphere));
  s.atmosphere.reset();
  EXPECT_FALSE(s.features() & feature_bit(SceneFeature::atmosphere));
}

TEST_F(AtmosphereConfig, TheHashChangesWithTheAtmosphereAndItsSunOnly) {
  const ScenePartMask part = part_bit(ScenePart::atmosphere);
  const Scene a = scene("{}"), same = scene("{}");
  EXPECT_EQ(a.hash(part), same.hash(part));
  auto changed = [&](auto edit) {
    Scene s = a;
    edit(s);
    return s.hash(part) != a.hash(part);
  };
  EXPECT_TRUE(changed([](Scene& s) { s.atmosphere->rayleigh_scattering[2] *= 1.0000001; }));
  EXPECT_TRUE(changed([](Scene& s) { s.atmosphere->mie_density.upper.exp_scale = -1.0 / 1300; }));
  EXPECT_TRUE(changed([](Scene& s) { s.atmosphere->absorption_density.lower.width = 24e3; }));
  EXPECT_TRUE(changed([](Scene& s) { s.atmosphere->mie_phase = MiePhase::henyey_greenstein; }));
  EXPECT_TRUE(changed([](Scene& s) { s.atmosphere->origin_altitude = 1; }));
  EXPECT_TRUE(changed([](Scene& s) { s.atmosphere->sun_angular_radius = 0.005; }));
  EXPECT_TRUE(changed([](Scene& s) { s.lights[0].direction = {0.1, -1, 0}; }));  // the sun moved
  EXPECT_TRUE(changed([](Scene& s) { s.lights[0].irradiance = {2, 2, 2}; }));
  EXPECT_TRUE(changed([](Scene& s) { s.atmosphere->sun_light = 2; }));  // another sun
  EXPECT_TRUE(changed([](Scene& s) { s.atmosphere.reset(); }));
  EXPECT_FALSE(changed([](Scene& s) { s.lights[2].direction = {1, -1, 0}; }));  // not the sun
  EXPECT_FALSE(changed([](Scene& s) { s.camera.position = {0, 100, 0}; }));
  EXPECT_FALSE(changed([](Scene& s) { s.atmosphere->preset = "custom"; }));  // a name; the values are equal
  // The other parts do not see the atmosphere.
  const ScenePartMask others = part_bit(ScenePart::camera) | part_bit(ScenePart::lights) | part_bit(ScenePart::media) |
                               part_bit(ScenePart::geometry) | part_bit(ScenePart::background);
  Scene b = a;
  b.atmosphere->mie_g = 0.5;
  EXPECT_EQ(a.hash(others), b.hash(others));
}

// NOAA's solar position (physics/sun_position.h) against known geometry. Tolerances: the
// series' stated 0.0006 rad (0.035°) for the declination plus its year's equinox, which
// falls at day 80 noon within 0.07° of declination 0 (the series gives −0.066° there).
double elevation_deg(const Vec3& toward_sun) { return std::asin(toward_sun[1]) * 180 / std::numbers::pi; }

TEST(SunPosition, AtTheEquatorOnTheEquinoxAtNoonTheSunIsAtTheZenith) {
  EXPECT_NEAR(elevation_deg(physics::sun_direction(12, 0, 80)), 90, 0.1);
}

TEST(SunPosition, AtTheEquatorOnTheEquinoxTheSunRisesInTheEastAndSetsInTheWest) {
  const Vec3 six = physics::sun_direction(6, 0, 80), eighteen = physics::sun_direction(18, 0, 80);
  EXPECT_NEAR(six[1], 0, 1e-12);  // on the horizon (cos h = 0 exactly at the equator)
  EXPECT_NEAR(eighteen[1], 0, 1e-12);
  EXPECT_GT(six[0], 0.9999);        // +X: east
  EXPECT_LT(eighteen[0], -0.9999);  // −X: west
}

TEST(SunPosition, AtLatitude45TheSolsticeNoonSunIs90Minus45PlusOrMinus23_44) {
  EXPECT_NEAR(elevation_deg(physics::sun_direction(12, 45, 172)), 90 - 45 + 23.44, 0.05);  // June 21
  EXPECT_NEAR(elevation_deg(physics::sun_direction(12, 45, 355)), 90 - 45 - 23.44, 0.05);  // December 21
  EXPECT_GT(physics::sun_direction(12, 45, 172)[2], 0);   // the noon sun of the north is in the south (+Z)
  EXPECT_LT(physics::sun_direction(12, -45, 172)[2], 0);  // and that of the south in the north (−Z)
}

TEST(SunPosition, IsAUnitVector) {
  for (double hours : {0.0, 3.3, 12.0, 19.9}) {
    for (double latitude : {-90.0, -30.0, 0.0, 61.5, 90.0}) {
      const Vec3 v = physics::sun_direction(hours, latitude, 200);
      EXPECT_NEAR(std::hypot(v[0], v[1], v[2]), 1, 1e-15);
    }
  }
}

}  // namespace
}  // namespace volgraph
