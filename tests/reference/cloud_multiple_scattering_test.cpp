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

}  // namespace
}  // namespace volgraph::reference
