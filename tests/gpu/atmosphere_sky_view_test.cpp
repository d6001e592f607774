// The sky pass's variants on both backends, where the scene has no surface: each against
// its double twin per pixel (physics/atmosphere_sky.h), the view from space against the
// CPU reference (reference/atmosphere_reference.h sky(), single scattering), the exact
// checks (no scattering: a black sky and the sun's disk E / (π sin²α) × T; the sky's
// symmetry about the sun's vertical plane; the limb-darkened disk), and the stress cases
// (a camera at 0 m to 1000 km looking at the horizon, the sun below it, a planet of 1 km):
// every value finite, the LUT passes too, and no seam at the horizon (horizon_seam).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"
#include "physics/camera.h"
#include "reference/atmosphere_reference.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kAtmosphereSkyViewWidth = 64, kAtmosphereSkyViewHeight = 36;

struct SkyCase {
  double altitude = 2;         // the camera's y (m; the scene's origin on the ground)
  double pitch = 0;            // the view's zenith cosine-ish: target = position + (0, pitch, -1)
  double sun_elevation = 0.35;  // rad, ahead of the camera (−z)
  std::string atmosphere = R"({ "preset": "earth" })";
  std::string variant = "sky_view_lut";
  std::string sky_params = "{}";
  std::string lut_params = "{}";  // the sky-view LUT's
  uint32_t width = kAtmosphereSkyViewWidth, height = kAtmosphereSkyViewHeight;
};

std::string number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string sky_config(const SkyCase& k) {
  const double y = k.altitude;
  const std::string sun = "[0, " + number(-std::sin(k.sun_elevation)) + ", " + number(std::cos(k.sun_elevation)) + "]";
  const std::string sky_view_input = k.variant == "sky_view_lut" ? R"("sky_view": "sky_view.sky_view", )" : "";
  return R"({ "output": { "size": [)" + std::to_string(k.width) + ", " + std::to_string(k.height) + R"(] },
  "scene": { "camera": { "position": [0, )" + number(y) + R"(, 0], "target": [0, )" + number(y + k.pitch) + R"(, -1], "fov_y_deg": 60 },
             "lights": [ { "name": "sun", "type": "directional", "direction": )" + sun + R"(, "irradiance": [2, 2, 2] } ],
             "atmosphere": )" + k.atmosphere + R"( },
  "graph": { "passes": [
    { "name": "lut", "type": "atmosphere_transmittance_lut" },
    { "name": "ms", "type": "atmosphere_multiscattering_lut", "inputs": { "transmittance": "lut.transmittance" } },
    { "name": "sky_view", "type": "atmosphere_skyview_lut", "params": )" + k.lut_params + R"(,
      "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } },
    { "name": "air", "type": "atmosphere_aerial_perspective",
      "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } },
    { "name": "lit", "type": "scene" },
    { "name": "lit_for_march", "type": "scene" },
    { "name": "sky", "type": "sky", "variant": ")" + k.variant + R"(", "params": )" + k.sky_params + R"(,
      "inputs": { "color": "lit.color", "depth": "lit.depth", "transmittance": "lut.transmittance", )" + sky_view_input +
         R"("multiscattering": "ms.multiscattering" } },
    { "name": "march", "type": "sky", "variant": "raymarch", "params": )" + k.sky_params + R"(,
      "inputs": { "color": "lit_for_march.color", "depth": "lit_for_march.depth", "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } } ],
    "outputs": ["sky.color", "sky_view.sky_view", "air.aerial_scattering", "air.aerial_transmittance", "march.color"] } })";
}

class SkyView : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const SkyCase& k) { return load_config_text("sky_view.json", sky_config(k), registry_); }
  // Every graph output after one frame: the sky (k.variant), the sky-view LUT, the aerial
  // perspective's two, the sky by the raymarch variant (the stress cases' second variant).
  std::vector<Texels> render(const LoadedConfig& config) {
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    std::vector<Texels> out;
    for (size_t i = 0; i < 5; ++i) out.push_back(executor.read_output(i));
    return out;
  }
  PassRegistry registry_;
};

Vec3 pixel_direction(const Camera& camera, uint32_t width, uint32_t height, uint32_t i, uint32_t j) {
  const physics::ViewRays rays = physics::view_rays(camera, double(width) / height);
  return physics::normalize(physics::view_ray(rays, (i + 0.5) / width * 2 - 1, 1 - (j + 0.5) / height * 2));
}

Vec3 texel(const Texels& image, uint32_t i, uint32_t j) {
  const size_t at = 4 * (size_t(j) * image.width + i);
  return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2]};
}

double sum_of(const Vec3& v) { return v[0] + v[1] + v[2]; }

// The twin of a pixel, E = 2 as the configs' sun: the march (raymarch, and sky_view_lut
// above the top) or, for sky_view_lut inside the atmosphere, the sky's integral the LUT
// holds plus the disk and the ground.
Vec3 twin_pixel(const Scene& scene, const SkyCase& k, const Vec3& d, const physics::SkyViewOptions& options) {
  const Atmosphere& a = *scene.atmosphere;
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  Vec3 l{};
  if (k.variant == "raymarch" || view.r > a.top_radius) {
    l = physics::marched_sky_radiance(a, view, d, {}, options);
  } else {
    const physics::SkyViewDirection sd = physics::sky_view_direction(view, d);
    const double r = std::min(view.r, a.top_radius);
    const Vec3 sky = physics::sky_scattering(a, r, sd.mu, view.mu_s, physics::view_sun_cosine(sd.mu, sd.cos_azimuth, view.mu_s), {},
                                             options.sampling);
    const Vec3 disk = physics::sun_disk_radiance(a, view, d, options.limb_darkening);
    const Vec3 ground = options.ground ? physics::seen_ground_radiance(a, view, d) : Vec3{0, 0, 0};
    for (size_t c = 0; c < 3; ++c) l[c] = sky[c] + disk[c] + ground[c];
  }
  return {2 * l[0], 2 * l[1], 2 * l[2]};
}

struct Errors {
  double mean = 0, largest = 0;  // relative: Σ|Δ| / Σ|twin| and the largest |Δ| / |twin| (pixels above `floor`)
};

// Relative error of `image` against the twin over every pixel whose twin is above `floor`
// (sum of rgb) and, when `skip_horizon`, at least `horizon_margin` in mu from the horizon
// (the sky-view LUT's texels there blend two sides of it).
Errors against_twin(const Texels& image, const Scene& scene, const SkyCase& k, const physics::SkyViewOptions& options, double floor,
                    double horizon_margin = 0) {
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  const double mu_h = physics::mu_horizon(*scene.atmosphere, std::min(view.r, scene.atmosphere->top_radius));
  Errors e;
  double sum = 0, sum_error = 0;
  for (uint32_t j = 0; j < image.height; ++j) {
    for (uint32_t i = 0; i < image.width; ++i) {
      const Vec3 d = pixel_direction(scene.camera, image.width, image.height, i, j);
      const double mu = d[0] * view.up[0] + d[1] * view.up[1] + d[2] * view.up[2];
      if (std::abs(mu - mu_h) < horizon_margin) continue;
      const Vec3 want = twin_pixel(scene, k, d, options), got = texel(image, i, j);
      if (sum_of(want) <= floor) continue;
      for (size_t c = 0; c < 3; ++c) {
        sum_error += std::abs(got[c] - want[c]);
        sum += want[c];
        if (want[c] > floor / 3) e.largest = std::max(e.largest, std::abs(got[c] - want[c]) / want[c]);
      }
    }
  }
  e.mean = sum > 0 ? sum_error / sum : 0;
  return e;
}

physics::SkyViewOptions single_scattering() { return {}; }

bool sky_view_texels_finite(const Texels& t) {
  return std::all_of(t.rgba.begin(), t.rgba.end(), [](float v) { return std::isfinite(v) && v >= 0; });
}

// The seam metric. Per column, the rows where the twin's ray goes from missing the ground to
// hitting it (the horizon; the planet's limb from space) make a pair; the pixel's jump
// across it, J = |L(above) − L(below)| (sum of rgb), is compared with the twin's: a seam is
// a jump the technique makes that the per-pixel truth does not (or the other way round).
// seam = max over columns of |J_gpu − J_twin| / max(J_twin, the twin's jumps between the
// two row pairs either side, 1e-3 × the pixels' radiance) — 0 for an image that steps at
// the horizon exactly as the truth does, 1 for a jump as large as the truth's whole step.
double horizon_seam(const Texels& image, const Scene& scene, const SkyCase& k, const physics::SkyViewOptions& options) {
  const Atmosphere& a = *scene.atmosphere;
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  double worst = 0;
  for (uint32_t i = 0; i < image.width; ++i) {
    for (uint32_t j = 1; j + 2 < image.height; ++j) {
      const auto hits = [&](uint32_t row) {
        const Vec3 d = pixel_direction(scene.camera, image.width, image.height, i, row);
        double r = std::max(view.r, a.bottom_radius), mu = d[0] * view.up[0] + d[1] * view.up[1] + d[2] * view.up[2];
        if (r > a.top_radius) {
          const std::optional<double> entry = physics::enter_atmosphere(a, r, mu);
          if (!entry) return false;
          mu = physics::mu_at(r, mu, *entry);
          r = a.top_radius;
        }
        return physics::ray_hits_ground(a, r, mu);
      };
      if (hits(j) || !hits(j + 1)) continue;
      std::array<double, 4> twin{}, got{};
      for (uint32_t n = 0; n < 4; ++n) {
        twin[n] = sum_of(twin_pixel(scene, k, pixel_direction(scene.camera, image.width, image.height, i, j - 1 + n), options));
        got[n] = sum_of(texel(image, i, j - 1 + n));
      }
      const double jump_twin = std::abs(twin[1] - twin[2]), jump_got = std::abs(got[1] - got[2]);
      const double scale = std::max({jump_twin, std::abs(twin[0] - twin[1]), std::abs(twin[2] - twin[3]),
                                     1e-3 * std::max(twin[1], twin[2])});
      if (scale > 0) worst = std::max(worst, std::abs(jump_got - jump_twin) / scale);
    }
  }
  return worst;
}

// ---- Each variant against its twin ----------------------------------------------------

// From 2 m, the sun 20° up ahead, single scattering (the LUTs' Ψ_ms off), the ground on:
// the raymarch against its double twin over every pixel (the ground's included): the LUTs'
// T_sun and float are what is left (measured on lavapipe: mean 3.0e-4, largest 9.2e-4).
TEST_P(SkyView, RaymarchMatchesTheDoubleTwin) {
  SkyCase k;
  k.variant = "raymarch";
  k.pitch = 0.1;
  k.sky_params = R"({ "multiscattering": false })";
  const LoadedConfig config = load(k);
  const std::vector<Texels> out = render(config);
  ASSERT_TRUE(sky_view_texels_finite(out[0]));
  const Errors e = against_twin(out[0], config.config.scene, k, single_scattering(), 1e-6);
  std::printf("raymarch from 2 m, single scattering, against the double twin: relative mean %.3g, largest %.3g\n", e.mean, e.largest);
  EXPECT_LT(e.mean, 2e-3);
  EXPECT_LT(e.largest, 5e-3);
}

// The LUT variant below the horizon: the ground through the transmittance LUT beside the
// LUT's in-scattering, against the twin away from the horizon's blended texels (0.02 in mu)
// (measured on lavapipe: mean 5.5e-4, largest 3.0e-3).
TEST_P(SkyView, SkyViewLutGroundMatchesTheDoubleTwin) {
  SkyCase k;
  k.altitude = 3000;
  k.pitch = -0.3;
  k.lut_params = R"({ "multiscattering": false })";
  k.sky_params = R"({ "multiscattering": false })";
  const LoadedConfig config = load(k);
  const std::vector<Texels> out = render(config);
  ASSERT_TRUE(sky_view_texels_finite(out[0]));
  const Errors e = against_twin(out[0], config.config.scene, k, single_scattering(), 1e-6, 0.02);
  std::printf("sky_view_lut from 3 km with the ground, single scattering, against the double twin: relative mean %.3g, largest %.3g\n",
              e.mean, e.largest);
  EXPECT_LT(e.mean, 3e-3);
  EXPECT_LT(e.largest, 1.5e-2);
}

// ---- The view from space ----------------------------------------------------------------

SkyCase from_space(const std::string& variant) {
  SkyCase k;
  k.altitude = 400e3;
  k.pitch = -0.3;
  k.sun_elevation = 0.17;
  k.variant = variant;
  k.sky_params = R"({ "multiscattering": false })";
  return k;
}

// From 400 km, looking down at the limb, the sun 10° up ahead: black space, the planet's
// limb, the lit ground — both variants (sky_view_lut falls back to the march above the top)
// against the double twin (measured on lavapipe: mean 3.4e-4, largest 9.3e-4), no value of
// the LUT passes (made at the top) not finite.
TEST_P(SkyView, FromSpaceBothVariantsMatchTheDoubleTwin) {
  for (const std::string variant : {"raymarch", "sky_view_lut"}) {
    const SkyCase k = from_space(variant);
    const LoadedConfig config = load(k);
    const std::vector<Texels> out = render(config);
    for (const Texels& t : out) ASSERT_TRUE(sky_view_texels_finite(t)) << variant;
    const Errors e = against_twin(out[0], config.config.scene, k, single_scattering(), 1e-6);
    std::printf("%s from 400 km, single scattering, against the double twin: relative mean %.3g, largest %.3g\n", variant.c_str(), e.mean,
                e.largest);
    EXPECT_LT(e.mean, 2e-3) << variant;
    EXPECT_LT(e.largest, 5e-3) << variant;
    // Space is black above the limb: the top rows' rays miss the atmosphere.
    EXPECT_EQ(sum_of(texel(out[0], 0, 0)), 0.0) << variant;
  }
}

// The same view against the CPU reference's sky() (double, adaptive Simpson; single
// scattering, its ground's sun term and the disk), 32x18: the error of the 40-sample march
// along rays up to the limb's ~2000 km (measured on lavapipe: mean 1.6e-3, largest 1.0e-2;
// the double twin's own mean 1.4e-3 — the march's sampling, not float, is most of it).
TEST_P(SkyView, FromSpaceAgainstTheReference) {
  SkyCase k = from_space("raymarch");
  k.width = 32;
  k.height = 18;
  const LoadedConfig config = load(k);
  const Texels image = render(config)[0];
  const Scene& scene = config.config.scene;
  const Atmosphere& a = *scene.atmosphere;
  const std::optional<reference::AtmosphereSun> sun = reference::scene_sun(a, scene.lights);
  ASSERT_TRUE(sun);
  reference::AtmosphereReferenceSettings settings;
  settings.samples = 0;
  settings.relative_tolerance = 1e-5;
  const reference::AtmosphereReference sky_reference(a, *sun, settings);
  const Vec3 eye = reference::planet_position(a, scene.camera.position);
  double sum = 0, sum_error = 0, worst = 0, sum_twin_error = 0;
  for (uint32_t j = 0; j < k.height; ++j) {
    for (uint32_t i = 0; i < k.width; ++i) {
      const Vec3 d = pixel_direction(scene.camera, k.width, k.height, i, j);
      const Vec3 want = sky_reference.sky(eye, d, 0).radiance, got = texel(image, i, j);
      const Vec3 twin = twin_pixel(scene, k, d, single_scattering());
      for (size_t c = 0; c < 3; ++c) {
        sum += want[c];
        sum_error += std::abs(got[c] - want[c]);
        sum_twin_error += std::abs(twin[c] - want[c]);
        if (want[c] > 1e-4) worst = std::max(worst, std::abs(got[c] - want[c]) / want[c]);
      }
    }
  }
  std::printf("raymarch from 400 km against the reference (single scattering): relative mean %.3g, largest %.3g; its double twin: mean %.3g\n",
              sum_error / sum, worst, sum_twin_error / sum);
  EXPECT_LT(sum_error / sum, 5e-3);
  EXPECT_LT(worst, 3e-2);
}

// ---- Exact checks ----------------------------------------------------------------------

// Without scattering (the ozone still absorbs) the sky is black and the disk, 0.05 rad so
// that pixel centres fall in it, is E / (π sin²α) × T (the transmittance LUT's): both
// variants, from the ground and from space (the unattenuated disk where its rays miss the air).
TEST_P(SkyView, WithoutScatteringTheSkyIsBlackAndTheDiskIsExact) {
  const std::string no_scattering =
      R"({ "preset": "earth", "rayleigh_scattering": [0, 0, 0], "mie_scattering": [0, 0, 0], "ground_albedo": [0, 0, 0], "sun": { "angular_radius": 0.05 } })";
  for (const std::string variant : {"raymarch", "sky_view_lut"}) {
    for (const double altitude : {2.0, 1000e3}) {
      SkyCase k;
      k.variant = variant;
      k.altitude = altitude;
      k.sun_elevation = altitude > 1e5 ? -0.05 : 0.2;  // from 1000 km the sun just above the planet's limb (through the air) or beside it
      k.pitch = altitude > 1e5 ? -0.05 : 0.2;
      k.atmosphere = no_scattering;
      const LoadedConfig config = load(k);
      const Texels image = render(config)[0];
      const Scene& scene = config.config.scene;
      const physics::AtmosphereView view = physics::atmosphere_view(scene);
      int disk_pixels = 0;
      for (uint32_t j = 0; j < kAtmosphereSkyViewHeight; ++j) {
        for (uint32_t i = 0; i < kAtmosphereSkyViewWidth; ++i) {
          const Vec3 disk = physics::sun_disk_radiance(*scene.atmosphere, view, pixel_direction(scene.camera, kAtmosphereSkyViewWidth, kAtmosphereSkyViewHeight, i, j));
          disk_pixels += disk[0] > 0;
          const Vec3 got = texel(image, i, j);
          for (size_t c = 0; c < 3; ++c) {
            ASSERT_NEAR(got[c], 2 * disk[c], 2e-3 * 2 * disk[c] + 1e-7) << variant << " at " << altitude << " m, pixel " << i << ", " << j;
          }
        }
      }
      EXPECT_GE(disk_pixels, 4) << variant << " at " << altitude << " m";
    }
  }
}

// The camera looks toward the sun's azimuth, so the sun's vertical plane is the image's
// vertical centre line: pixel (i, j) and (W − 1 − i, j) see mirrored directions, the same
// sky. Both variants, multiple scattering on, from the ground and from space; the largest
// relative difference (measured on lavapipe: 0 for both; bounded at 1e-6, float's rounding).
TEST_P(SkyView, TheSkyIsSymmetricAboutTheSunsVerticalPlane) {
  for (const std::string variant : {"raymarch", "sky_view_lut"}) {
    for (const double altitude : {2.0, 400e3}) {
      SkyCase k;
      k.variant = variant;
      k.altitude = altitude;
      k.pitch = altitude > 1e5 ? -0.3 : 0.2;
      k.sun_elevation = altitude > 1e5 ? -0.2 : 0.35;
      const Texels image = render(load(k))[0];
      double worst = 0;
      for (uint32_t j = 0; j < kAtmosphereSkyViewHeight; ++j) {
        for (uint32_t i = 0; i < kAtmosphereSkyViewWidth / 2; ++i) {
          const Vec3 left = texel(image, i, j), right = texel(image, kAtmosphereSkyViewWidth - 1 - i, j);
          for (size_t c = 0; c < 3; ++c) {
            const double scale = std::max(std::abs(left[c]), std::abs(right[c]));
            if (scale > 1e-6) worst = std::max(worst, std::abs(left[c] - right[c]) / scale);
          }
        }
      }
      std::printf("%s at %g m: largest left/right relative difference %.3g\n", variant.c_str(), altitude, worst);
      EXPECT_LT(worst, 1e-6) << variant << " at " << altitude << " m";
    }
  }
}

// The limb-darkened disk (0.05 rad, no scattering) keeps E: its pixels against the twin
// (limb_darkening × E / (π sin²α) × T), and the centre brighter than the uniform disk.
TEST_P(SkyView, TheLimbDarkenedDiskMatchesItsTwin) {
  SkyCase k;
  k.variant = "raymarch";
  k.sun_elevation = 0.2;
  k.pitch = 0.2;
  k.sky_params = R"({ "limb_darkening": true })";
  k.atmosphere = R"({ "preset": "earth", "rayleigh_scattering": [0, 0, 0], "mie_scattering": [0, 0, 0], "ground_albedo": [0, 0, 0], "sun": { "angular_radius": 0.05 } })";
  const LoadedConfig config = load(k);
  const Texels image = render(config)[0];
  const Scene& scene = config.config.scene;
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  int brighter = 0;
  for (uint32_t j = 0; j < kAtmosphereSkyViewHeight; ++j) {
    for (uint32_t i = 0; i < kAtmosphereSkyViewWidth; ++i) {
      const Vec3 d = pixel_direction(scene.camera, kAtmosphereSkyViewWidth, kAtmosphereSkyViewHeight, i, j);
      const Vec3 want = physics::sun_disk_radiance(*scene.atmosphere, view, d, true);
      const Vec3 uniform = physics::sun_disk_radiance(*scene.atmosphere, view, d, false);
      const Vec3 got = texel(image, i, j);
      brighter += got[2] > 2 * uniform[2] * 1.01;
      for (size_t c = 0; c < 3; ++c) ASSERT_NEAR(got[c], 2 * want[c], 2e-3 * 2 * want[c] + 1e-7) << "pixel " << i << ", " << j;
    }
  }
  EXPECT_GE(brighter, 1) << "the disk's centre outshines the uniform disk";
}

// ---- Stress --------------------------------------------------------------------------

// A camera at 0 m, 1 mm, 10 km, 100 km and 1000 km looking at the horizon (its forward
// direction's zenith cosine 0: |mu| < 1e-6), the sun 20° up or 6° below the horizon, on the
// earth and on a planet of 1 km radius (60 km of air): every output of the sky, the
// sky-view LUT and the aerial perspective finite and ≥ 0 on both variants, and the
// horizon's seam (horizon_seam, at 32x18) below kMarchSeam and kLutSeam: printed. From 10 km
// up, a second view looks down at the planet's limb (from 100 km the 1 km planet falls
// between the pixels' centres: nothing to measure there).
// About 5× the largest measured on lavapipe (3.7e-3 and 1.3e-2, the earth from 10 km).
constexpr double kMarchSeam = 0.02, kLutSeam = 0.06;

TEST_P(SkyView, StressCasesAreFiniteAndSeamless) {
  const std::string tiny = R"({ "preset": "earth", "bottom_radius": 1000, "top_radius": 61000 })";
  for (const std::string& atmosphere : {std::string(R"({ "preset": "earth" })"), tiny}) {
    for (const double altitude : {0.0, 1e-3, 10e3, 100e3, 1000e3}) {
      for (const double sun : {0.35, -0.1}) {
        SkyCase k;
        k.atmosphere = atmosphere;
        k.altitude = altitude;
        k.sun_elevation = sun;
        k.width = 32;
        k.height = 18;
        k.sky_params = k.lut_params = R"({ "multiscattering": false })";  // as the twin
        const std::string what = std::string(atmosphere == tiny ? "the 1 km planet" : "the earth") + " at " + number(altitude) +
                                 " m, sun at " + number(sun) + " rad";
        for (const bool at_limb : {false, true}) {
          const LoadedConfig config = load(k);
          const Scene& scene = config.config.scene;
          const physics::AtmosphereView view = physics::atmosphere_view(scene);
          if (!at_limb) {
            const double mu = -view.up[2];  // the forward direction (0, 0, −1)'s zenith cosine
            ASSERT_LT(std::abs(mu), 1e-6) << what;
          }
          const std::vector<Texels> out = render(config);
          for (const Texels& t : out) ASSERT_TRUE(sky_view_texels_finite(t)) << what;
          for (const std::string variant : {"sky_view_lut", "raymarch"}) {
            SkyCase seen = k;
            seen.variant = variant;
            const double seam = horizon_seam(out[variant == "raymarch" ? 4 : 0], scene, seen, physics::SkyViewOptions{});
            std::printf("%s on %s, forward %s: horizon seam %.3g\n", variant.c_str(), what.c_str(), at_limb ? "at the limb" : "at mu = 0",
                        seam);
            EXPECT_LT(seam, variant == "raymarch" ? kMarchSeam : kLutSeam) << variant << " on " << what;
          }
          if (altitude < 1e3) break;
          // From high up the planet's limb is below the frame: look at it.
          const double mu_limb = physics::mu_horizon(*scene.atmosphere, view.r);
          k.pitch = mu_limb / std::sqrt(1 - mu_limb * mu_limb);
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, SkyView, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
