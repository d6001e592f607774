// The GPU sky (the `sky` pass at its default variant, from the LUT chain of
// configs/tests/atmosphere_sky.json: 64x36, 60° by 91°, 2 m above the earth preset's
// ground) against the CPU reference (reference/atmosphere_reference.h), on Vulkan
// (lavapipe) under the validation layer, at noon (sun 60° up) and at sunset (2° up), the
// sun 20° right of the view.
// Compared: every 4th pixel of each row and column (16×9 of the 64x36 image, pixel centres)
// at least 1° above the horizon, the sky's scattering alone (the sun's disk off on the GPU,
// left out of the reference: both draw it by the same transmittance). Metric: relative mean
// error Σ|gpu − ref| / Σ ref over those pixels' channels, and the signed Σ(gpu − ref) / Σ ref.
// - Single scattering (the sky-view LUT's multiple-scattering term off, the reference's
//   Monte Carlo off: exact to its quadrature's 1e-6): within 0.5 % (Hillaire 2020's goal)
//   at the default 192x108 and for the per-pixel march (sky variant raymarch); printed
//   per LUT size.
// - The full sky (every order; the reference's orders ≥ 2 by 64 paths a pixel): its error
//   per sky-view LUT size, printed with the reference's noise beside it (the Monte Carlo's
//   standard error per pixel over its value, mean over the pixels, and the standard error
//   of the signed sum) and bounded at the default size (10 %).
// Measured on lavapipe, single scattering, noon / sunset: sky view 48x27 0.46 % / 1.2 %,
// 96x54 0.11 % / 0.22 %, 192x108 0.11 % / 0.075 % (largest pixel 0.23 % / 0.29 %),
// 384x216 0.13 % / 0.13 %; the march 0.082 % / 0.098 %. The full sky 6.2-6.3 % at noon,
// 6.5-7.0 % at sunset at every LUT size and for the march (signed −4.5 ± 0.3 %, −6.9 ±
// 0.3 %; the reference's noise 4 % a pixel).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "passes/passes.h"
#include "physics/camera.h"
#include "reference/atmosphere_reference.h"
#include "reference/image_render.h"
#include "tests/accuracy/vulkan_accuracy_test.h"
#include "tests/gpu/backends.h"
#include "tests/support/fog_accuracy.h"
#include "tests/support/source_dir.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 36, kStride = 4;
const std::string kConfig = std::string(::volgraph::testing::source_dir()) + "/configs/tests/atmosphere_sky.json";

// The sun `elevation_deg` up, 20° right of the camera's azimuth (−z), as a light's
// direction of travel.
Vec3 sun_travel(double elevation_deg) {
  const double e = elevation_deg * M_PI / 180, az = 20 * M_PI / 180;
  return {-std::cos(e) * std::sin(az), -std::sin(e), std::cos(e) * std::cos(az)};
}

// The reference's sky at the compared pixels (NaN where not compared), its scattering
// alone, with the Monte Carlo's relative standard error of each.
struct SkyReference {
  std::vector<Vec3> radiance;  // kWidth × kHeight
  std::vector<Vec3> standard_error;
  size_t compared = 0;
};

SkyReference reference_sky(const Scene& scene, uint32_t paths) {
  const Atmosphere& a = *scene.atmosphere;
  reference::AtmosphereReferenceSettings settings;
  settings.samples = paths;
  const reference::AtmosphereReference air(a, *reference::scene_sun(a, scene.lights), settings);
  const Vec3 eye = reference::planet_position(a, scene.camera.position);
  SkyReference out{std::vector<Vec3>(kWidth * kHeight, Vec3{NAN, NAN, NAN}), std::vector<Vec3>(kWidth * kHeight, Vec3{0, 0, 0})};
  reference::render_pixels(
      [&](uint32_t ii, uint32_t jj) {
        const uint32_t i = ii * kStride + kStride / 2, j = jj * kStride + kStride / 2;
        const Vec3 d = physics::pixel_ray(scene.camera, kWidth, kHeight, i, j);
        if (d[1] < std::sin(M_PI / 180)) return Vec3{0, 0, 0};  // the camera's zenith is +y
        const uint64_t key = uint64_t(j) * kWidth + i;
        const reference::SkySample s = air.sky(eye, d, key);
        out.radiance[key] = s.scattering.total;
        for (size_t c = 0; c < 3; ++c) {
          double variance = 0;
          for (uint32_t k = 1; k < s.scattering.orders; ++k) variance += std::pow(s.scattering.standard_error[k][c], 2);
          out.standard_error[key][c] = std::sqrt(variance);
        }
        return Vec3{0, 0, 0};
      },
      {.width = kWidth / kStride, .height = kHeight / kStride, .threads = 0});
  out.compared = size_t(std::count_if(out.radiance.begin(), out.radiance.end(), [](const Vec3& v) { return !std::isnan(v[0]); }));
  return out;
}

struct SkyError {
  double relative_mean = 0;         // Σ|gpu − ref| / Σ ref
  double signed_relative = 0;       // Σ(gpu − ref) / Σ ref
  double largest = 0;               // the largest |gpu − ref| / ref of a channel
  double noise_per_pixel = 0;       // the reference's standard error over its value, mean over the channels
  double noise_of_signed_sum = 0;   // √Σ se² / Σ ref
};

SkyError sky_error(const Texels& gpu, const SkyReference& ref) {
  double sum_abs = 0, sum_signed = 0, sum = 0, variance = 0, noise = 0;
  SkyError e;
  size_t n = 0;
  for (size_t p = 0; p < ref.radiance.size(); ++p) {
    if (std::isnan(ref.radiance[p][0])) continue;
    for (size_t c = 0; c < 3; ++c) {
      const double g = gpu.rgba[4 * p + c], r = ref.radiance[p][c];
      EXPECT_TRUE(std::isfinite(g)) << "pixel " << p;
      sum_abs += std::abs(g - r);
      sum_signed += g - r;
      sum += r;
      variance += ref.standard_error[p][c] * ref.standard_error[p][c];
      noise += ref.standard_error[p][c] / r;
      e.largest = std::max(e.largest, std::abs(g - r) / r);
      ++n;
    }
  }
  e.relative_mean = sum_abs / sum;
  e.signed_relative = sum_signed / sum;
  e.noise_per_pixel = noise / double(n);
  e.noise_of_signed_sum = std::sqrt(variance) / sum;
  return e;
}

class AtmosphereSkyAccuracy : public VulkanAccuracyTest {
 protected:
  // The config with its sun `elevation_deg` up, the sky-view LUT at width × height with its
  // multiple-scattering term on or off, the sun's disk off.
  // `variant` "raymarch": the sky pass's per-pixel march instead (its own multiple-scattering
  // term likewise).
  LoadedConfig sky(double elevation_deg, bool multiscattering, int width = 192, int height = 108, const std::string& variant = "sky_view_lut") {
    const std::string ms = multiscattering ? "true" : "false";
    LoadedConfig loaded = accuracy::load_linear(
        kConfig, registry_,
        {.sets = {"sky_view.multiscattering=" + ms, "sky.multiscattering=" + ms, "sky_view.width=" + std::to_string(width),
                  "sky_view.height=" + std::to_string(height), "sky.sun_disk=false"},
         .variants = {"sky=" + variant}});
    loaded.config.scene.lights[0].direction = sun_travel(elevation_deg);
    return loaded;
  }
  Texels render(const LoadedConfig& loaded) { return accuracy::render_gpu(gpu_->device(), loaded); }

};

TEST_F(AtmosphereSkyAccuracy, SingleScatteringIsWithinHalfAPercentOfTheReference) {
  for (const double elevation : {60.0, 2.0}) {
    const SkyReference ref = reference_sky(sky(elevation, false).config.scene, 0);
    for (const auto& [w, h] : {std::pair{48, 27}, {96, 54}, {192, 108}, {384, 216}}) {
      const SkyError e = sky_error(render(sky(elevation, false, w, h)), ref);
      std::printf("single scattering, sun %g° up, sky view %dx%d, %zu pixels: relative mean error %.3g (signed %.3g), largest %.3g\n",
                  elevation, w, h, ref.compared, e.relative_mean, e.signed_relative, e.largest);
      if (w == 192) EXPECT_LT(e.relative_mean, 5e-3) << "sun " << elevation << "° up";
    }
    const SkyError march = sky_error(render(sky(elevation, false, 192, 108, "raymarch")), ref);
    std::printf("single scattering, sun %g° up, per-pixel march (40 samples): relative mean error %.3g (signed %.3g), largest %.3g\n",
                elevation, march.relative_mean, march.signed_relative, march.largest);
    EXPECT_LT(march.relative_mean, 5e-3) << "sun " << elevation << "° up, raymarch";
  }
}

TEST_F(AtmosphereSkyAccuracy, FullSkyErrorPerSkyViewLutSize) {
  constexpr uint32_t kPaths = 64;
  for (const double elevation : {60.0, 2.0}) {
    const SkyReference ref = reference_sky(sky(elevation, true).config.scene, kPaths);
    const SkyError march = sky_error(render(sky(elevation, true, 192, 108, "raymarch")), ref);
    std::printf("full sky, sun %g° up, per-pixel march (40 samples): relative mean error %.3g, signed %.3g ± %.2g\n", elevation,
                march.relative_mean, march.signed_relative, march.noise_of_signed_sum);
    for (const auto& [w, h] : {std::pair{48, 27}, {96, 54}, {192, 108}, {384, 216}}) {
      const SkyError e = sky_error(render(sky(elevation, true, w, h)), ref);
      std::printf("full sky, sun %g° up, sky view %dx%d, %zu pixels: relative mean error %.3g, signed %.3g ± %.2g (the "
                  "reference's standard error), largest %.3g; the reference's noise per pixel %.3g (%u paths)\n",
                  elevation, w, h, ref.compared, e.relative_mean, e.signed_relative, e.noise_of_signed_sum, e.largest, e.noise_per_pixel,
                  kPaths);
      if (w != 192) continue;
      // Measured at the default size: 6.3 % (signed −4.5 ± 0.3 %) at noon, 7.0 % (−6.9 ± 0.3 %)
      // at sunset: Hillaire 2020's isotropic Ψ_ms falls short of the orders ≥ 2, whatever
      // the LUT's size (its error is the same to 0.5 % from 48x27 to 384x216).
      EXPECT_LT(e.relative_mean, 0.1) << "sun " << elevation << "° up";
      EXPECT_LT(std::abs(e.signed_relative), 0.1) << "sun " << elevation << "° up";
    }
  }
}

}  // namespace
}  // namespace volgraph::testing
