// cloud_march (passes/clouds/cloud_march.cpp) at its defaults against the cloud layer's CPU
// reference (reference/clouds.h: the same noise, density and lighting text, the view and
// light marches integrated to convergence) on the cloud oracle scenes
// (configs/tests/oracle_clouds*.json: 48 × 27, a cumulus layer from the ground and from
// above, no surface in view), on Vulkan (lavapipe) under the validation layer.
// Metric, over every pixel of the march's `clouds` image (rgb radiance, a transmittance):
// - radiance: relative RMSE √(Σ(gpu − ref)²) / √(Σ ref²) over the rgb channels, and the
//   worst pixel: the largest |gpu − ref| of a channel over the image's largest ref;
// - transmittance: RMSE and the largest |gpu − ref| (absolute: T is in [0, 1]).
// What the GPU's march differs in is its quadrature alone: `steps` equal steps with
// empty-space skipping and early termination at T < 1e-3, 16 light samples over 2 km, the
// fine samples jittered per pixel (off: midpoints).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "physics/camera.h"
#include "reference/clouds.h"
#include "tests/accuracy/vulkan_accuracy_test.h"
#include "tests/support/fog_accuracy.h"
#include "tests/support/source_dir.h"

// A named namespace: the accuracy tests build as one unity source, so the fog test's
// anonymous names (kTestConfigs, kOracles) would collide.
namespace volgraph::testing::cloud_accuracy {

const char* const kCloudMarch = "cloud_march";  // the pass under test (tests/pass_labels.cmake reads the name)
const std::string kTestConfigs = std::string(::volgraph::testing::source_dir()) + "/configs/tests/";

// The reference's clouds image: per pixel radiance and transmittance.
struct CloudImage {
  uint32_t width = 0, height = 0;
  std::vector<double> rgbt;  // 4 a pixel
};

CloudImage reference_clouds(const LoadedConfig& loaded, const reference::CloudReferenceSettings& reference_settings) {
  const Scene& scene = loaded.config.scene;
  const reference::CloudReference clouds(scene, reference_settings);
  CloudImage out{loaded.config.output_size.width, loaded.config.output_size.height, {}};
  out.rgbt.resize(size_t(out.width) * out.height * 4);
  reference::RenderSettings settings{.width = out.width, .height = out.height};
  reference::render_pixels(
      [&](uint32_t i, uint32_t j) {
        const reference::CloudSample s = clouds.along(physics::pixel_ray(scene.camera, out.width, out.height, i, j),
                                                      std::numeric_limits<double>::infinity());
        const size_t k = (size_t(j) * out.width + i) * 4;
        out.rgbt[k] = s.radiance[0], out.rgbt[k + 1] = s.radiance[1], out.rgbt[k + 2] = s.radiance[2], out.rgbt[k + 3] = s.transmittance;
        return s.radiance;
      },
      settings);
  return out;
}

// The reference at the settings the loaded graph gives.
CloudImage reference_clouds(const LoadedConfig& loaded) {
  return reference_clouds(loaded, reference::cloud_reference_settings(loaded.graph, loaded.params));
}

struct CloudError {
  double radiance_rmse = 0, radiance_worst = 0, transmittance_rmse = 0, transmittance_worst = 0, cloudy_fraction = 0;
  bool finite = true;
  std::string describe() const {
    char text[256];
    std::snprintf(text, sizeof text, "radiance relative RMSE %.4f, worst pixel %.4f of the peak; transmittance RMSE %.4f, worst %.4f (%.0f %% of pixels cloudy)",
                  radiance_rmse, radiance_worst, transmittance_rmse, transmittance_worst, 100 * cloudy_fraction);
    return text;
  }
};

CloudError compare(const Texels& gpu, const CloudImage& ref) {
  EXPECT_EQ(gpu.width, ref.width);
  EXPECT_EQ(gpu.height, ref.height);
  CloudError e;
  double squared = 0, ref_squared = 0, peak = 0, worst = 0, t_squared = 0;
  size_t cloudy = 0;
  const size_t pixels = ref.rgbt.size() / 4;
  for (size_t p = 0; p < pixels; ++p) {
    for (size_t c = 0; c < 4; ++c) {
      const double g = gpu.rgba[4 * p + c], r = ref.rgbt[4 * p + c], d = std::abs(g - r);
      if (!std::isfinite(g)) e.finite = false;
      if (c < 3) {
        squared += d * d, ref_squared += r * r, peak = std::max(peak, r), worst = std::max(worst, d);
      } else {
        t_squared += d * d, e.transmittance_worst = std::max(e.transmittance_worst, d);
        if (r < 0.99) ++cloudy;
      }
    }
  }
  e.radiance_rmse = ref_squared > 0 ? std::sqrt(squared / ref_squared) : std::sqrt(squared);
  e.radiance_worst = peak > 0 ? worst / peak : worst;
  e.transmittance_rmse = std::sqrt(t_squared / double(pixels));
  e.cloudy_fraction = double(cloudy) / double(pixels);
  return e;
}

// Measured bounds (docs/clouds.md "Measured error"), with margin.
struct Oracle {
  const char* config;
  double radiance_rmse, radiance_worst, transmittance_rmse, transmittance_worst;
};
const Oracle kOracles[] = {
    // measured 0.0474, 0.0831, 0.0009, 0.0121 (lavapipe, 16 light samples, jitter on:
    // one frame's noise; 6 light samples, midpoints, before: 0.0417, 0.0351, 0.0012, 0.0253);
    // about 25 % margin
    {"oracle_clouds.json", 0.06, 0.105, 0.0012, 0.016},
    // measured 0.0240, 0.0563, 0.0016, 0.0361 (6 light samples before: 0.2102, 0.2729: the
    // sunlit tops, where 6 samples over 2 km misjudged the optical depth toward the sun)
    {"oracle_clouds_above.json", 0.03, 0.07, 0.002, 0.045},
};
// With a weather map (cloud_weather_map's texture in both the march and the reference):
// measured 0.1132, 0.2268, 0.0043, 0.0616 (lavapipe, jitter on; the front's tall clouds at
// coverage 0.8: 256 steps and 64 toward the sun, midpoints, give 0.0137, 0.0350, 0.0021,
// 0.0260, so it is the march's quadrature); about 25 % margin.
const Oracle kWeatherOracle = {"oracle_clouds_weather.json", 0.14, 0.28, 0.0055, 0.077};
// The same without jitter (each fine sample at its step's midpoint): measured 0.0200,
// 0.0220, 0.0012, 0.0253 and 0.0254, 0.0697, 0.0020, 0.0556.
const Oracle kMidpointOracles[] = {
    {"oracle_clouds.json", 0.025, 0.028, 0.0016, 0.032},
    {"oracle_clouds_above.json", 0.032, 0.087, 0.0026, 0.07},
};
const char* const kMidpoints = "march.jitter=false";  // the quadrature tests below: no per-pixel noise

class CloudAccuracy : public VulkanAccuracyTest {
 protected:
  LoadedConfig oracle(const std::string& config, const Overrides& overrides = {}) {
    return accuracy::load_linear(kTestConfigs + config, registry_, overrides);
  }
  CloudError error_of(const LoadedConfig& loaded, const CloudImage& ref, const std::string& what) {
    const CloudError e = compare(accuracy::render_gpu(gpu_->device(), loaded), ref);
    std::printf("  %s, %s: %s\n", kCloudMarch, what.c_str(), e.describe().c_str());
    return e;
  }
};

TEST_F(CloudAccuracy, CloudMarchAtItsDefaultsIsWithinItsBoundOnEveryOracle) {
  for (const Oracle& o : kOracles) {
    const LoadedConfig loaded = oracle(o.config);
    const CloudError e = error_of(loaded, reference_clouds(loaded), std::string("cloud_march defaults on ") + o.config);
    EXPECT_TRUE(e.finite) << o.config;
    EXPECT_GT(e.cloudy_fraction, 0.1) << o.config << ": the oracle must see cloud";
    EXPECT_LE(e.radiance_rmse, o.radiance_rmse) << o.config;
    EXPECT_LE(e.radiance_worst, o.radiance_worst) << o.config;
    EXPECT_LE(e.transmittance_rmse, o.transmittance_rmse) << o.config;
    EXPECT_LE(e.transmittance_worst, o.transmittance_worst) << o.config;
  }
}

TEST_F(CloudAccuracy, CloudMarchWithAWeatherMapAgreesWithTheReference) {
  const Oracle& o = kWeatherOracle;
  const LoadedConfig loaded = oracle(o.config);
  const CloudError e = error_of(loaded, reference_clouds(loaded), std::string("cloud_march with a weather map on ") + o.config);
  EXPECT_TRUE(e.finite);
  EXPECT_GT(e.cloudy_fraction, 0.1) << "the oracle must see cloud";
  EXPECT_LT(e.cloudy_fraction, 0.95) << "and clear sky where the map is dark";
  EXPECT_LE(e.radiance_rmse, o.radiance_rmse);
  EXPECT_LE(e.radiance_worst, o.radiance_worst);
  EXPECT_LE(e.transmittance_rmse, o.transmittance_rmse);
  EXPECT_LE(e.transmittance_worst, o.transmittance_worst);
  // The residual is the march's quadrature, not a mismatch of the maps: more steps, less error.
  const LoadedConfig fine = oracle(o.config, {.sets = {kMidpoints, "march.steps=256", "march.light_steps=64"}});
  const CloudError f = error_of(fine, reference_clouds(fine), std::string("cloud_march 256 steps, 64 toward the sun, on ") + o.config);
  EXPECT_LT(f.radiance_rmse, 0.5 * e.radiance_rmse);
  EXPECT_LT(f.transmittance_rmse, 0.7 * e.transmittance_rmse);
}

// The jitter's cost in one frame: each fine sample moved within its step per pixel (what a
// temporal pass averages over frames) against the midpoints at the same settings.
TEST_F(CloudAccuracy, CloudMarchJitterOffIsWithinItsBoundOnEveryOracle) {
  for (const Oracle& o : kMidpointOracles) {
    const LoadedConfig loaded = oracle(o.config, {.sets = {kMidpoints}});
    const CloudError e = error_of(loaded, reference_clouds(loaded), std::string("cloud_march jitter off on ") + o.config);
    EXPECT_TRUE(e.finite) << o.config;
    EXPECT_LE(e.radiance_rmse, o.radiance_rmse) << o.config;
    EXPECT_LE(e.radiance_worst, o.radiance_worst) << o.config;
    EXPECT_LE(e.transmittance_rmse, o.transmittance_rmse) << o.config;
    EXPECT_LE(e.transmittance_worst, o.transmittance_worst) << o.config;
  }
}

// More view steps, less transmittance error: 64 → 128 → 256 (light_steps 16, midpoints), on both
// oracles, in the worst pixel (measured 0.0253 → 0.0082 → 0.0039 from the ground, 0.0556 →
// 0.0160 → 0.0125 from above; the RMSE floors at 8e-4 from 128 steps on, about half's step
// just below 1, 4.9e-4: the rgba16f output's). The radiance's error does not fall with `steps` (measured: docs/clouds.md): it
// is the light march's, the next test.
TEST_F(CloudAccuracy, CloudMarchTransmittanceErrorFallsAsStepsGrow) {
  for (const Oracle& o : kOracles) {
    const CloudImage ref = reference_clouds(oracle(o.config));
    double previous = 0;
    for (int steps : {64, 128, 256}) {
      const CloudError e = error_of(oracle(o.config, {.sets = {kMidpoints, "march.steps=" + std::to_string(steps)}}), ref,
                                    std::string(o.config) + ", steps " + std::to_string(steps));
      if (steps > 64) EXPECT_LT(e.transmittance_worst, previous) << o.config << " steps " << steps;
      previous = e.transmittance_worst;
    }
  }
}

// More light samples, less radiance error: light_steps 6 → 16 → 64 at 256 view steps.
TEST_F(CloudAccuracy, CloudMarchRadianceErrorFallsAsLightStepsGrow) {
  for (const Oracle& o : kOracles) {
    const CloudImage ref = reference_clouds(oracle(o.config));
    double previous = 0;
    for (int light_steps : {6, 16, 64}) {
      const CloudError e = error_of(oracle(o.config, {.sets = {kMidpoints, "march.steps=256", "march.light_steps=" + std::to_string(light_steps)}}),
                                    ref, std::string(o.config) + ", steps 256, light_steps " + std::to_string(light_steps));
      if (light_steps > 6) EXPECT_LT(e.radiance_rmse, previous) << o.config << " light_steps " << light_steps;
      previous = e.radiance_rmse;
    }
    // Converged on both sides, the two agree (measured 0.0052 and 0.0027): the same text.
    EXPECT_LE(previous, 0.01) << o.config << ": steps 256, light_steps 64 against the reference";
  }
}

// With cloud_phase_table's Mie phase wired into the march, the reference reads the same
// texels through the same lookup (cloud_phase_table.h) and octaves (cloud_octaves_tabulated):
// the residual is the march's quadrature, as on oracle_clouds.json: measured 0.0188, 0.0178,
// 0.0012, 0.0253 (lavapipe, jitter off), bounded as that oracle's midpoints. Against the
// reference without the table (the dual-lobe HG) the radiance is 0.30 off: the bound fails
// if the table were ignored on either side.
TEST_F(CloudAccuracy, CloudMarchWithAMiePhaseTableAgreesWithTheReference) {
  const Oracle o = {"oracle_clouds_mie.json", 0.025, 0.028, 0.0016, 0.032};
  const LoadedConfig loaded = oracle(o.config, {.sets = {kMidpoints}});
  const reference::CloudReferenceSettings settings = reference::cloud_reference_settings(loaded.graph, loaded.params);
  ASSERT_TRUE(settings.phase_table.has_value()) << "the wired table reaches the reference";
  const CloudError e = error_of(loaded, reference_clouds(loaded, settings), std::string("cloud_march with the Mie table on ") + o.config);
  EXPECT_TRUE(e.finite);
  EXPECT_GT(e.cloudy_fraction, 0.1) << "the oracle must see cloud";
  EXPECT_LE(e.radiance_rmse, o.radiance_rmse);
  EXPECT_LE(e.radiance_worst, o.radiance_worst);
  EXPECT_LE(e.transmittance_rmse, o.transmittance_rmse);
  EXPECT_LE(e.transmittance_worst, o.transmittance_worst);
  reference::CloudReferenceSettings without_table = settings;
  without_table.phase_table.reset();
  const CloudError ignored = error_of(loaded, reference_clouds(loaded, without_table), "the same against the reference's dual-lobe HG");
  EXPECT_GT(ignored.radiance_rmse, 4 * o.radiance_rmse) << "the table must matter on this oracle";
}

}  // namespace volgraph::testing::cloud_accuracy
