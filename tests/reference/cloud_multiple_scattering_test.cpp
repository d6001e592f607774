// The cloud layer's brute-force multiple scattering (reference/cloud_path_tracer.h): one
// bounce is the CPU reference's single scattering, a white slab conserves energy, and the
// measured error of Wrenninge's octaves against it (docs/clouds.md "Multiple scattering
// against brute force").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "physics/camera.h"
#include "physics/cloud_lighting.h"
#include "physics/vec3.h"
#include "reference/cloud_path_tracer.h"
#include "reference/clouds.h"
#include "tests/reference/test_scenes.h"

namespace volgraph::reference {
namespace {

constexpr double kNoSurface = std::numeric_limits<double>::infinity();
constexpr uint32_t kOracleWidth = 12, kOracleHeight = 7;

// A config's scene and cloud settings; light_distance long enough to reach the layer's top
// from its bottom toward the oracles' sun 30° up (2.5 km / sin 30° = 5 km), so that the
// reference's light march and the walk's ratio tracking see the same optical depth.
struct CloudCase {
  LoadedConfig loaded;
  CloudReferenceSettings settings;
};

CloudCase cloud_case(const char* config, double light_distance = 6000) {
  CloudCase c{load_shipped(config, kOracleWidth, kOracleHeight), {}};
  c.settings = cloud_reference_settings(c.loaded.graph, c.loaded.params);
  c.settings.view_steps = 1024, c.settings.light_steps = int(64 * light_distance / 1000);
  c.settings.light_distance = light_distance;
  return c;
}

double rgb_sum(const Vec3& v) { return v[0] + v[1] + v[2]; }

Vec3 pixel_direction(const Scene& scene, uint32_t i, uint32_t j) { return physics::pixel_ray(scene.camera, kOracleWidth, kOracleHeight, i, j); }

// Pixels of oracle_clouds (12 × 7) whose rays see the layer: thin edges (T 0.02–0.17) and
// the thick bases.
const std::vector<std::array<uint32_t, 2>> kGroundPixels = {{0, 3}, {1, 3}, {10, 4}, {11, 4}, {8, 6}, {5, 1}, {0, 0}, {9, 4}};

TEST(CloudMultipleScattering, OneBounceIsTheReferencesSingleScattering) {
  CloudCase c = cloud_case("tests/oracle_clouds.json");
  c.settings.octaves = 1;
  const CloudReference clouds(c.loaded.config.scene, c.settings);
  int lit = 0;
  for (const auto& [i, j] : kGroundPixels) {
    const Vec3 d = pixel_direction(c.loaded.config.scene, i, j);
    const CloudSample reference = clouds.along(d, kNoSurface);
    const CloudRadianceEstimate walk = cloud_multiple_scattering(clouds, d, kNoSurface, {.bounces = 1, .samples = 2048}, cloud_pixel_seed(i, j));
    if (rgb_sum(reference.radiance) > 0.01) ++lit;
    for (size_t k = 0; k < 3; ++k)  // 3 standard errors, plus the reference's own tolerance
      EXPECT_NEAR(walk.radiance[k], reference.radiance[k], 3 * walk.standard_error[k] + kCloudReferenceTolerance * reference.radiance[k] + 1e-6)
          << "pixel " << i << "," << j;
  }
  EXPECT_GE(lit, 3);  // the case sees lit cloud
}

// The walk's directions follow cloud_phase: the mean cosine (1 − w) g_f + w g_b and the
// histogram of cosθ against the phase's integral over each bin (each within 4 standard errors).
TEST(CloudMultipleScattering, SampledDirectionsFollowTheCloudPhase) {
  const CloudWalkLight light{.g_forward = 0.8, .g_back = -0.3, .back_weight = 0.2};
  constexpr int kSamples = 400000, kBins = 20;
  CloudRandom random(5);
  const Vec3 axis = physics::normalize(Vec3{0.3, -0.5, 0.8});
  std::vector<int> histogram(kBins, 0);
  double mean_cosine = 0;
  for (int s = 0; s < kSamples; ++s) {
    const double c = std::clamp(physics::dot(sample_cloud_phase(light, axis, random), axis), -1.0, 1.0);
    mean_cosine += c / kSamples;
    ++histogram[size_t(std::min(int((c + 1) / 2 * kBins), kBins - 1))];
  }
  EXPECT_NEAR(mean_cosine, 0.8 * 0.8 + 0.2 * -0.3, 4 * 0.6 / std::sqrt(double(kSamples)));
  for (int b = 0; b < kBins; ++b) {
    double expected = 0;  // 2π ∫ p(cosθ) dcosθ over the bin, by the midpoint rule on 200 points
    for (int k = 0; k < 200; ++k) {
      const double c = -1 + (b + (k + 0.5) / 200) * 2.0 / kBins;
      expected += 2 * std::numbers::pi * physics::cloud_lighting::cloud_phase(float(c), 0.8f, -0.3f, 0.2f) * (2.0 / kBins / 200);
    }
    const double observed = double(histogram[size_t(b)]) / kSamples;
    EXPECT_NEAR(observed, expected, 4 * std::sqrt(expected * (1 - expected) / kSamples) + 1e-4) << "bin " << b;
  }
}

// A plane-parallel slab 0 ≤ y ≤ thickness of constant σt under a sun overhead (the test's
// density hook; the layer's noise never is constant). Majorant 2σt: ratio tracking's
// weights are then 2^−k rather than 0 or 1.
class WhiteSlab final : public CloudWalkMedium {
 public:
  WhiteSlab(double sigma_t, double thickness) : sigma_t_(sigma_t), thickness_(thickness) {}
  double sigma_t(const Vec3& p) const override { return p[1] >= 0 && p[1] <= thickness_ ? sigma_t_ : 0; }
  double majorant() const override { return 2 * sigma_t_; }
  double exit_distance(const Vec3& p, const Vec3& d) const override {
    if (d[1] > 0) return (thickness_ - p[1]) / d[1];
    if (d[1] < 0) return p[1] / -d[1];
    return 1e30;
  }
  bool ground_hides_sun(const Vec3&) const override { return false; }

 private:
  double sigma_t_, thickness_;
};

struct Flux {
  double mean = 0, standard_error = 0;
};

// The flux leaving the slab's face at height y0 toward side `up` (+1 the top, −1 the bottom):
// π × the mean radiance over cosine-weighted views into the slab.
Flux scattered_flux(const WhiteSlab& slab, const CloudWalkLight& light, double y0, double up, int paths, int bounces) {
  CloudRandom random(up > 0 ? 11 : 12);
  double sum = 0, sum_squares = 0;
  for (int s = 0; s < paths; ++s) {
    const double mu = std::sqrt(random.uniform());
    const Vec3 d = physics::around(Vec3{0, -up, 0}, mu, 2 * std::numbers::pi * random.uniform());
    const Vec3 origin{0, y0, 0};
    const double value = std::numbers::pi * trace_cloud_path(slab, light, origin, d, 0, slab.exit_distance(origin, d), bounces, random).radiance[0];
    sum += value, sum_squares += value * value;
  }
  const double mean = sum / paths;
  return {mean, std::sqrt(std::max(sum_squares / paths - mean * mean, 0.0) / (paths - 1))};
}

// Albedo 1: reflected + diffusely transmitted + the sun's direct beam e^−τ0 = the incident
// E μ0 (E = 1, μ0 = 1), within 3 standard errors; a walk cut at one bounce loses energy.
TEST(CloudMultipleScattering, WhiteSlabConservesEnergy) {
  const double thickness = 1000;
  for (const double tau : {1.0, 4.0}) {
    const WhiteSlab slab(tau / thickness, thickness);
    const CloudWalkLight light{.has_sun = true, .to_sun = {0, 1, 0}, .sun_irradiance = {1, 1, 1}};
    auto total = [&](int bounces, Flux& sigma) {
      const Flux reflected = scattered_flux(slab, light, thickness, 1, 200000, bounces);
      const Flux transmitted = scattered_flux(slab, light, 0, -1, 200000, bounces);
      sigma.standard_error = std::hypot(reflected.standard_error, transmitted.standard_error);
      std::printf("tau %.0f bounces %d: R %.4f T_diffuse %.4f direct %.4f total %.4f ± %.4f\n", tau, bounces, reflected.mean,
                  transmitted.mean, std::exp(-tau), reflected.mean + transmitted.mean + std::exp(-tau), sigma.standard_error);
      return reflected.mean + transmitted.mean + std::exp(-tau);
    };
    Flux all, one;
    EXPECT_NEAR(total(100000, all), 1.0, 3 * all.standard_error) << "tau " << tau;
    EXPECT_LT(total(1, one), 1.0 - 3 * one.standard_error) << "tau " << tau;
  }
}

// One pixel's measurement: the brute force and the reference's octaves, in rgb sums.
struct OctaveFigures {
  uint32_t i = 0, j = 0;
  double transmittance = 1, brute = 0, brute_error = 0, octaves3 = 0, octaves3_2km = 0, octaves1 = 0;
  int orders_for_99_percent = 0;
};

// The first scattering order by which the sun's part reaches 99 % of its sum.
int orders_for_99_percent(const std::vector<double>& by_order) {
  double total = 0, running = 0;
  for (double v : by_order) total += v;
  for (size_t k = 0; k < by_order.size(); ++k)
    if ((running += by_order[k]) >= 0.99 * total) return int(k + 1);
  return int(by_order.size());
}

std::vector<OctaveFigures> measure_octaves(const char* config, const std::vector<std::array<uint32_t, 2>>& pixels) {
  CloudCase c = cloud_case(config);
  c.settings.view_steps = 512;
  CloudReferenceSettings single = c.settings, short_light = c.settings;
  single.octaves = 1;
  short_light.light_distance = 2000, short_light.light_steps = 128;  // cloud_march's light_distance
  const Scene& scene = c.loaded.config.scene;
  const CloudReference octaves(scene, c.settings), one(scene, single), shipped(scene, short_light);
  std::vector<OctaveFigures> out;
  for (const auto& [i, j] : pixels) {
    const Vec3 d = pixel_direction(scene, i, j);
    const CloudSample r3 = octaves.along(d, kNoSurface);
    const CloudRadianceEstimate walk = cloud_multiple_scattering(octaves, d, kNoSurface, {.bounces = 1024, .samples = 1024}, cloud_pixel_seed(i, j));
    out.push_back({i, j, r3.transmittance, rgb_sum(walk.radiance), rgb_sum(walk.standard_error), rgb_sum(r3.radiance),
                   rgb_sum(shipped.along(d, kNoSurface).radiance), rgb_sum(one.along(d, kNoSurface).radiance),
                   orders_for_99_percent(walk.by_order)});
    const OctaveFigures& f = out.back();
    std::printf("%s %2u,%u T %.3f brute %.4f ± %.4f | oct3/brute %.3f (2 km light %.3f) | oct1/brute %.3f | 99%% by order %d\n", config, i, j,
                f.transmittance, f.brute, f.brute_error, f.octaves3 / f.brute, f.octaves3_2km / f.brute, f.octaves1 / f.brute, f.orders_for_99_percent);
  }
  return out;
}

// Wrenninge's octaves at the defaults (3, a = b = c = 0.5) against the brute force, per
// pixel: the ratio octaves / brute force of the rgb radiance (1 is exact), and the same for
// single scattering (octaves 1). The bounds are the measured figures with margin
// (docs/clouds.md, "Multiple scattering against brute force").
TEST(CloudMultipleScattering, OctavesAgainstBruteForce) {
  const std::vector<std::array<uint32_t, 2>> above = {{2, 2}, {5, 2}, {8, 2}, {3, 4}, {6, 4}, {9, 4}, {4, 6}, {7, 6}};
  for (const char* config : {"tests/oracle_clouds.json", "tests/oracle_clouds_above.json"}) {
    const bool from_ground = std::string(config) == "tests/oracle_clouds.json";
    for (const OctaveFigures& f : measure_octaves(config, from_ground ? kGroundPixels : above)) {
      EXPECT_GT(f.brute, 3 * f.brute_error) << f.i << "," << f.j;  // the brute force resolves the pixel
      EXPECT_GE(f.octaves3, f.octaves1) << f.i << "," << f.j;       // the octaves only add light
      // Measured 0.004–0.93 from the ground, 0.30–0.58 from above: the octaves fall short.
      EXPECT_LT(f.octaves3, 1.25 * f.brute) << f.i << "," << f.j;
      if (!from_ground) EXPECT_GT(f.octaves3, 0.2 * f.brute) << f.i << "," << f.j;
      if (!from_ground) EXPECT_LT(f.octaves3, 0.8 * f.brute) << f.i << "," << f.j;
      EXPECT_LT(f.orders_for_99_percent, 1024) << f.i << "," << f.j;  // the bounce cap is not what ends the walks
    }
  }
}

}  // namespace
}  // namespace volgraph::reference
