// The cloud layer's lighting (shaders/include/cloud_lighting.h, compiled as C++ by
// physics/cloud_lighting.h): the dual-lobe phase normalised, the octaves' single-scattering
// case, Wrenninge's a ≤ b energy bound, the powder term, and no NaN or infinity anywhere.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/cloud_lighting.h"

namespace volgraph::physics {
namespace {

using namespace cloud_lighting;

constexpr double kCloudPi = 3.14159265358979323846;

// ∫ f(cosθ) dω over the sphere = 2π ∫_{−1}^{1} f(μ) dμ, by the midpoint rule in θ (dense near the peaks).
template <typename F>
double sphere_integral(F f) {
  constexpr int n = 20000;
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const double theta = (k + 0.5) * kCloudPi / n;
    sum += f(float(std::cos(theta))) * std::sin(theta) * (kCloudPi / n);
  }
  return 2 * kCloudPi * sum;
}

// The octave sum integrated over the sphere: σs Σ b^i T(a^i τ) (each lobe normalised).
double octaves_energy(float tau, int octaves, float a, float b, float c) {
  return sphere_integral([&](float mu) { return cloud_octaves(1.0f, tau, mu, 0.8f, -0.3f, 0.2f, octaves, a, b, c); });
}

TEST(CloudLighting, DualLobePhaseIsNormalisedOverTheSphere) {
  for (const float g_forward : {0.0f, 0.5f, 0.8f, 0.9f})
    for (const float g_back : {-0.5f, -0.3f, 0.0f})
      for (const float w : {0.0f, 0.2f, 0.5f, 1.0f}) {
        const double integral = sphere_integral([&](float mu) { return cloud_phase(mu, g_forward, g_back, w); });
        EXPECT_NEAR(integral, 1.0, 2e-4) << "g_forward " << g_forward << " g_back " << g_back << " w " << w;
      }
}

TEST(CloudLighting, DualLobePhaseMixesTheTwoLobes) {
  EXPECT_FLOAT_EQ(cloud_phase(0.3f, 0.8f, -0.3f, 0.0f), phase_hg(0.8f, 0.3f));
  EXPECT_FLOAT_EQ(cloud_phase(0.3f, 0.8f, -0.3f, 1.0f), phase_hg(-0.3f, 0.3f));
  EXPECT_GT(cloud_phase(1.0f, 0.8f, -0.3f, 0.2f), cloud_phase(-1.0f, 0.8f, -0.3f, 0.2f));  // forward peak
}

TEST(CloudLighting, OneOctaveIsSingleScatteringExactly) {
  for (const float tau : {0.0f, 0.1f, 1.0f, 7.5f, 100.0f})
    for (const float mu : {-1.0f, -0.2f, 0.0f, 0.6f, 1.0f}) {
      const float single = 0.05f * cloud_phase(mu, 0.8f, -0.3f, 0.2f) * std::exp(-tau);
      EXPECT_EQ(cloud_octaves(0.05f, tau, mu, 0.8f, -0.3f, 0.2f, 1, 0.5f, 0.5f, 0.5f), single) << tau << " " << mu;
    }
}

TEST(CloudLighting, MoreOctavesAddLightInsideTheCloud) {
  const float one = cloud_octaves(0.05f, 4.0f, 0.5f, 0.8f, -0.3f, 0.2f, 1, 0.5f, 0.5f, 0.5f);
  const float three = cloud_octaves(0.05f, 4.0f, 0.5f, 0.8f, -0.3f, 0.2f, 3, 0.5f, 0.5f, 0.5f);
  EXPECT_GT(three, 2.0f * one);
}

// Wrenninge's condition: with a ≤ b the energy of the octaves over the sphere never passes
// σs Σ_{i<N} b^i ≤ σs / (1 − b), the single lobe's energy σs summed as a geometric series;
// an a above b is read as b.
TEST(CloudLighting, OctavesWithAAtMostBStayWithinTheSingleLobeEnergyBound) {
  for (const float b : {0.25f, 0.5f, 0.75f})
    for (const float a : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f})
      for (const float tau : {0.0f, 0.5f, 3.0f, 30.0f})
        for (const int n : {1, 2, 3, 8}) {
          double bound = 0, weight = 1;
          for (int i = 0; i < n; ++i, weight *= b) bound += weight;
          EXPECT_LE(octaves_energy(tau, n, a, b, 0.5f), bound * (1 + 1e-4)) << a << " " << b << " " << tau << " " << n;
          EXPECT_LE(bound, 1.0 / (1.0 - b) + 1e-9);
        }
}

TEST(CloudLighting, AAboveBIsReadAsB) {
  for (const float tau : {0.3f, 3.0f})
    EXPECT_EQ(cloud_octaves(0.05f, tau, 0.4f, 0.8f, -0.3f, 0.2f, 4, 0.9f, 0.5f, 0.5f),
              cloud_octaves(0.05f, tau, 0.4f, 0.8f, -0.3f, 0.2f, 4, 0.5f, 0.5f, 0.5f));
}

TEST(CloudLighting, PowderIsOneWhenOffAndDarkensTheSunlitEdgeWhenOn) {
  for (const float tau : {0.0f, 0.1f, 5.0f}) EXPECT_EQ(cloud_powder(tau, 0.0f), 1.0f);
  EXPECT_EQ(cloud_powder(0.0f, 1.0f), 0.0f);
  EXPECT_NEAR(cloud_powder(50.0f, 1.0f), 2.0f, 1e-6f);  // not physical: above 1 inside the cloud
}

TEST(CloudLighting, FiniteEverywhere) {
  const std::vector<float> cosines{-1.0f, -0.999f, 0.0f, 0.999f, 1.0f};
  const std::vector<float> gs{-0.999f, -0.3f, 0.0f, 0.8f, 0.999f};
  const std::vector<float> unit{0.0f, 0.5f, 1.0f};
  for (const float mu : cosines)
    for (const float g : gs)
      for (const float w : unit)
        for (const float tau : {0.0f, 1.0f, 1e6f, 1e30f})
          for (const float abc : unit)
            for (const int n : {0, 1, 3, 8, 100}) {
              const float v = cloud_octaves(1e3f, tau, mu, g, -g, w, n, abc, abc, abc);
              ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << mu << " " << g << " " << w << " " << tau << " " << abc << " " << n;
              ASSERT_TRUE(std::isfinite(cloud_powder(tau, w)));
            }
}

}  // namespace
}  // namespace volgraph::physics
