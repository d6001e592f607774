// Media maths (physics/media.h): the stable (1 − e^(−x))/x in float against
// double across the traps the naive form falls into; Hillaire's step exact for a
// homogeneous slab at any slice count and more accurate than Wronski's on a dense one;
// height-fog optical depth against quadrature; depth fog and σ from a transmittance
// colour at their edges; transmittance in [0, 1] and finite over the stress ranges.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/media.h"

namespace volgraph::physics {
namespace {

double exact_one_minus_exp_over_x(double x) { return x == 0 ? 1.0 : -std::expm1(-x) / x; }

TEST(Media, OneMinusExpOverXKeepsFloatPrecisionWhereTheNaiveFormFails) {
  for (float x : {0.0f, 1e-9f, 1e-7f, 1e-5f, 1e-3f, 0.00999f, 0.01f, 0.0101f, 0.5f, 1.0f, 30.0f, 1e4f, -1e-6f, -0.5f, -20.0f}) {
    const double exact = exact_one_minus_exp_over_x(double(x));
    EXPECT_NEAR(one_minus_exp_over_x(x) / exact, 1.0, 2e-6) << "x " << x;
  }
  // The traps (float32): 1.0014 at 1e-5, 1.19 at 1e-7, 0 at 1e-9, NaN at 0.
  auto naive = [](float x) { return (1.0f - std::exp(-x)) / x; };
  EXPECT_GT(std::abs(naive(1e-5f) - 1.0f), 1e-3f);
  EXPECT_GT(std::abs(naive(1e-7f) - 1.0f), 0.1f);
  EXPECT_EQ(naive(1e-9f), 0.0f);
  EXPECT_TRUE(std::isnan(naive(0.0f)));
}

TEST(Media, OneMinusExpOverXIsFiniteForHugeNegativeArguments) {
  for (float x : {-80.0f, -100.0f, -1e6f}) EXPECT_TRUE(std::isfinite(one_minus_exp_over_x(x))) << x;
}

// A homogeneous slab of depth D with constant in-scattering S: exactly S(1 − e^(−σt D))/σt.
double slab(double s, double sigma_t, double depth) { return s * depth * exact_one_minus_exp_over_x(sigma_t * depth); }

template <typename Step>
ScatterAccumulator<double> march(Step step, double s, double sigma_t, double depth, int slices) {
  ScatterAccumulator<double> a;
  for (int i = 0; i < slices; ++i) step(a, s, sigma_t, depth / slices);
  return a;
}

TEST(Media, HillaireIsExactForAHomogeneousSlabAtAnySliceCount) {
  for (double sigma_t : {0.0, 1e-30, 1e-6, 0.1, 1.0, 50.0, 1e4}) {
    for (int slices : {1, 4, 64}) {
      const auto a = march(integrate_hillaire<double>, 2.0, sigma_t, 3.0, slices);
      EXPECT_NEAR(a.radiance / slab(2.0, sigma_t, 3.0), 1.0, 1e-12) << "σt " << sigma_t << " slices " << slices;
      const double t = std::exp(-sigma_t * 3.0);
      EXPECT_NEAR(a.transmittance, t, 1e-13 * t);  // a product of up to 64 factors
    }
  }
}

TEST(Media, WronskiConvergesAndHillaireBeatsItOnADenseMedium) {
  const double sigma_t = 5.0, depth = 2.0, want = slab(1.0, sigma_t, depth);  // optical depth 10
  double previous_error = 1e9;
  for (int slices : {8, 16, 32, 64}) {
    const double wronski_error = std::abs(march(integrate_wronski<double>, 1.0, sigma_t, depth, slices).radiance - want);
    const double hillaire_error = std::abs(march(integrate_hillaire<double>, 1.0, sigma_t, depth, slices).radiance - want);
    EXPECT_LT(wronski_error, previous_error);   // converges with slices
    EXPECT_LT(hillaire_error, wronski_error);   // and stays behind the energy-conserving step
    previous_error = wronski_error;
  }
}

TEST(Media, IntegrationStepsStayFiniteAndBoundedOverTheStressRanges) {
  for (float sigma_t : {0.0f, 1e-7f, 1e-3f, 1.0f, 1e2f, 1e4f}) {
    for (float dz : {1e-3f, 1.0f, 1e3f, 1e5f}) {
      ScatterAccumulator<float> w, h;
      integrate_wronski(w, 1.0f, sigma_t, dz);
      integrate_hillaire(h, 1.0f, sigma_t, dz);
      for (const auto& a : {w, h}) {
        ASSERT_TRUE(std::isfinite(a.radiance)) << sigma_t << " " << dz;
        ASSERT_GE(a.transmittance, 0.0f);
        ASSERT_LE(a.transmittance, 1.0f);
      }
      ASSERT_LE(h.radiance, dz * (1 + 1e-6f));  // never more light than an empty slice gathers
    }
  }
}

// Simpson's rule with 2e5 intervals on σ(y(t)).
double height_fog_quadrature(double sigma_base, double falloff, double base, double y0, double dy, double length) {
  const int n = 200000;
  const double h = length / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    sum += w * sigma_base * std::exp(-falloff * (y0 + dy * i * h - base));
  }
  return sum * h / 3;
}

TEST(Media, HeightFogOpticalDepthMatchesQuadrature) {
  struct Case { double falloff, y0, dy, length; };
  for (const Case& c : {Case{0.1, 2, 0, 100}, Case{0.1, 2, 0.5, 100}, Case{0.1, 2, -0.5, 100}, Case{2.0, 10, -1, 12},
                        Case{1e-6, 0, 1, 1000}, Case{0.5, -5, 0.01, 50}}) {
    const double want = height_fog_quadrature(0.05, c.falloff, 1.0, c.y0, c.dy, c.length);
    EXPECT_NEAR(height_fog_optical_depth(0.05, c.falloff, 1.0, c.y0, c.dy, c.length) / want, 1.0, 1e-9)
        << c.falloff << " " << c.y0 << " " << c.dy << " " << c.length;
  }
  EXPECT_TRUE(std::isfinite(height_fog_optical_depth(0.05f, 10.0f, 0.0f, -1000.0f, 1.0f, 1e5f)));
}

TEST(Media, DepthFogFactorsAtTheirEdges) {
  EXPECT_EQ(depth_fog_linear(5.0, 10.0, 20.0), 1.0);
  EXPECT_EQ(depth_fog_linear(15.0, 10.0, 20.0), 0.5);
  EXPECT_EQ(depth_fog_linear(25.0, 10.0, 20.0), 0.0);
  EXPECT_EQ(depth_fog_linear(25.0, 20.0, 20.0), 0.0);  // degenerate range: a step
  EXPECT_DOUBLE_EQ(depth_fog_exponential(4.0, 0.25), std::exp(-1.0));
  EXPECT_DOUBLE_EQ(depth_fog_exponential_squared(4.0, 0.25), std::exp(-1.0));
  EXPECT_EQ(depth_fog_exponential_squared(0.0, 0.25), 1.0);
  EXPECT_EQ(depth_fog_exponential(1e30f, 1.0f), std::exp(-80.0f));
}

TEST(Media, SigmaFromATransmittanceColourHandlesZeroAndOne) {
  EXPECT_DOUBLE_EQ(sigma_t_from_transmittance(0.5, 2.0), std::log(2.0) / 2.0);
  EXPECT_EQ(sigma_t_from_transmittance(1.0, 2.0), 0.0);
  const double opaque = sigma_t_from_transmittance(0.0, 2.0);
  EXPECT_TRUE(std::isfinite(opaque));
  EXPECT_DOUBLE_EQ(opaque, -std::log(kMinTransmittance<double>) / 2.0);
  EXPECT_TRUE(std::isfinite(sigma_t_from_transmittance(0.0f, 0.0f)));
}

}  // namespace
}  // namespace volgraph::physics
