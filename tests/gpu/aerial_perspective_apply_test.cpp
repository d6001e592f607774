// Where the atmosphere meets the scene, on both backends:
// - the sun through the air and the sky's ambient light a Lambertian plane:
//   L = ρ/π (E·T_sun·cos θ + π·L_sky), T_sun and L_sky from physics/atmosphere_lighting.h
//   (the functions the reference lights with), within two fp16 steps of the colour;
// - aerial_perspective_apply reads the aerial-perspective volumes at each pixel's surface
//   distance as its CPU twin does (physics::aerial_perspective_slice: the slice coordinate
//   and the ramp in front of the first texel), the distance from the read-back depth and the
//   volume interpolated on the CPU: an emissive sphere around the camera, once past the
//   first texel (radius 2.5 slices) and once inside the ramp (0.2 slice), within two fp16
//   steps plus the depth's float rounding; the same with the volumes of the bruneton
//   variant (its lookup frame written as the hillaire variant's);
// - sky pixels (nothing drawn) keep the sky's colour exactly.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_lighting.h"
#include "physics/atmosphere_lut.h"
#include "physics/camera.h"
#include "tests/gpu/backends.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr const char* kApplySun = R"({ "name": "sun", "type": "directional", "direction": [0, -0.5, -0.8660254], "irradiance": [2, 2, 2] })";

std::string plane_config() {
  return std::string(R"({ "output": { "size": [8, 8] },
  "scene": { "camera": { "position": [0, 3, 0.001], "target": [0, 0, 0], "fov_y_deg": 20 },
             "materials": { "ground": { "albedo": [0.5, 0.5, 0.5] } },
             "objects": [ { "shape": "plane", "size": [10, 1, 10], "material": "ground" } ],
             "lights": [ )") + kApplySun + R"( ],
             "atmosphere": { "preset": "earth", "origin_altitude": 500 } },
  "graph": { "passes": [ { "name": "lit", "type": "scene" } ], "outputs": ["lit.color"] } })";
}

// A sphere of `radius` m around the camera, emitting radiance 1 and reflecting nothing,
// seen through the air; the aerial-perspective volume as large as the frame (each pixel
// centre a column's centre), 8 slices over 8 km.
std::string sphere_config(double radius, const std::string& variant) {
  const std::string r = std::to_string(radius);
  const std::string bruneton = variant == "bruneton" ? R"(
    { "name": "tables", "type": "atmosphere_bruneton_tables", "params": { "nu": 4, "nu_mu_s": 32, "mu": 16, "r": 4, "orders": 2 },
      "inputs": { "transmittance": "lut.transmittance" } },)" : "";
  const std::string volume_inputs = variant == "bruneton" ? R"("scattering": "tables.scattering", "single_mie_scattering": "tables.single_mie_scattering")" : R"("multiscattering": "ms.multiscattering")";
  return std::string(R"({ "output": { "size": [16, 16] },
  "scene": { "camera": { "position": [0, 2, 0], "target": [0, 2.5, -10], "fov_y_deg": 60, "near": 0.5, "far": 20000 },
             "materials": { "glow": { "albedo": [0, 0, 0], "emissive": [1, 1, 1] } },
             "objects": [ { "shape": "sphere", "size": [)") + r + ", " + r + ", " + r + R"(], "material": "glow",
                            "transform": { "translate": [0, 2, 0] } } ],
             "lights": [ )" + kApplySun + R"( ],
             "atmosphere": { "preset": "earth" } },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "lut", "type": "atmosphere_transmittance_lut" },
    { "name": "ms", "type": "atmosphere_multiscattering_lut", "inputs": { "transmittance": "lut.transmittance" } },)" + bruneton + R"(
    { "name": "aerial", "type": "atmosphere_aerial_perspective", "variant": ")" + variant + R"(",
      "params": { "resolution": 16, "slices": 8, "distance": 8000 },
      "inputs": { "transmittance": "lut.transmittance", )" + volume_inputs + R"( } },
    { "name": "air", "type": "aerial_perspective_apply",
      "inputs": { "color": "lit.color", "depth": "lit.depth", "aerial_scattering": "aerial.aerial_scattering",
                  "aerial_transmittance": "aerial.aerial_transmittance", "lookup": "aerial.lookup" } } ],
    "outputs": ["air.color", "lit.depth", "aerial.aerial_scattering", "aerial.aerial_transmittance"] } })";
}

class AtmosphereApply : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const std::string& text) { return load_config_text("atmosphere_apply.json", text, registry_); }
  PassRegistry registry_;
};


TEST_P(AtmosphereApply, TheSunThroughTheAirAndTheSkyLightALambertPlane) {
  const LoadedConfig config = load(plane_config());
  const Scene& scene = config.config.scene;
  Executor executor(device(), config.graph, &scene, {});
  executor.run_frame();
  const Texels color = executor.read_output(0);
  const Atmosphere& a = *scene.atmosphere;
  const double mu_s = 0.5;  // the sun 30° up; the plane faces up
  const Vec3 t_sun = physics::sun_transmittance(a, a.bottom_radius + a.origin_altitude, mu_s);
  const Vec3 sky = physics::sky_ambient_radiance(scene);
  for (size_t c = 0; c < 3; ++c) {
    // The air takes something off and the sky adds something: neither is a no-op.
    ASSERT_LT(t_sun[c], 0.95);
    ASSERT_GT(sky[c], 1e-3);
    const double want = 0.5 / M_PI * (2 * t_sun[c] * mu_s + M_PI * sky[c]);
    for (uint32_t p = 0; p < color.width * color.height; ++p) {
      EXPECT_NEAR(color.rgba[4 * p + c], want, fp16_steps(want)) << "pixel " << p << " channel " << c;
    }
  }
}

// The CPU twin of the apply pass's lookup at pixel (i, j) of a frame as large as the
// volume: the column's texels interpolated along the slices at the surface's distance.
struct Expected {
  Vec3 radiance{0, 0, 0};
  double w = 0;
};

Expected expected_pixel(const Texels& scattering, const Texels& transmittance, const Texels& depth, const Camera& camera,
                        const Vec3& sun, uint32_t i, uint32_t j, double distance) {
  const uint32_t n = scattering.width, slices = scattering.depth;
  const double d = depth.rgba[4 * (j * n + i)];
  const double view_depth = camera.near * camera.far / (camera.far - d * (camera.far - camera.near));
  const Vec3 ray = physics::pixel_ray(camera, n, n, i, j);  // unit
  const Vec3 forward = physics::view_rays(camera, 1.0).forward;
  const double along_axis = ray[0] * forward[0] + ray[1] * forward[1] + ray[2] * forward[2];
  const physics::AerialSlice slice = physics::aerial_perspective_slice(view_depth / along_axis, distance, int(slices));
  const double z = slice.w * slices - 0.5;
  const uint32_t k0 = uint32_t(std::floor(z)), k1 = std::min(k0 + 1, slices - 1);
  const double f = z - k0;
  Expected e{{0, 0, 0}, slice.w};
  for (size_t c = 0; c < 3; ++c) {
    const auto at = [&](const Texels& t, uint32_t k) { return double(t.rgba[4 * ((k * n + j) * n + i) + c]); };
    const double s = (1 - f) * at(scattering, k0) + f * at(scattering, k1);
    const double tr = (1 - f) * at(transmittance, k0) + f * at(transmittance, k1);
    e.radiance[c] = 1 - (1 - tr) * slice.ramp + s * sun[c] * slice.ramp;
  }
  return e;
}

void expect_apply_matches_its_twin(Executor& executor, const Scene& scene, double radius, double distance) {
  const Texels color = executor.read_output(0), depth = executor.read_output(1);
  const Texels scattering = executor.read_output(2), transmittance = executor.read_output(3);
  ASSERT_EQ(scattering.width, color.width);
  const Vec3 sun = scene.lights[0].irradiance;
  double farthest = 0;
  for (uint32_t j = 0; j < color.height; ++j) {
    for (uint32_t i = 0; i < color.width; ++i) {
      const Expected e = expected_pixel(scattering, transmittance, depth, scene.camera, sun, i, j, distance);
      farthest = std::max(farthest, e.w * distance);
      for (size_t c = 0; c < 3; ++c) {
        const double got = color.rgba[4 * (j * color.width + i) + c];
        EXPECT_NEAR(got, e.radiance[c], fp16_steps(e.radiance[c]) + 2e-4) << "pixel " << i << "," << j << " channel " << c;
      }
    }
  }
  EXPECT_NEAR(farthest, std::max(radius, 0.5 * distance / scattering.depth), 0.02 * radius);
}

TEST_P(AtmosphereApply, ReadsTheAirAtEachSurfacesDistance) {
  for (const auto& [radius, variant] : {std::pair{2500.0, "hillaire"}, {100.0, "hillaire"}, {2500.0, "bruneton"}}) {
    SCOPED_TRACE("sphere radius " + std::to_string(radius) + ", " + variant);
    const LoadedConfig config = load(sphere_config(radius, variant));
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    expect_apply_matches_its_twin(executor, config.config.scene, radius, 8000);
    // Past a slice's worth of air the surface's emission is visibly changed.
    const Texels color = executor.read_output(0);
    if (radius > 1000) EXPECT_LT(color.rgba[2], 0.99) << "the air in front of the sphere dims it";
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereApply, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
