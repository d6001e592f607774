// The error figures of tools/compare/metrics.h on images with known answers: identical
// images, a constant offset, SSIM by hand and under noise, masks, non-finite values, a
// black reference, the metric names.
#include "tools/compare/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "tests/compare/test_images.h"
#include "tools/compare/flip.h"
#include "tools/compare/ssim.h"

namespace volgraph::compare {
namespace {

using test_images::checkerboard;
using test_images::constant;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// A coloured HDR image with structure at several scales, values 0.02 … 6.
RgbImage textured(uint32_t w, uint32_t h) {
  RgbImage image = constant(w, h, {0, 0, 0});
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      float* p = &image.rgb[3 * (size_t(y) * w + x)];
      const float check = ((x / 4 + y / 4) % 2) ? 1.0f : 0.25f;
      p[0] = 0.02f + 6.0f * check * float(x) / float(w);
      p[1] = 0.5f + 0.4f * std::sin(0.3f * float(x + 2 * y));
      p[2] = 0.1f + 0.8f * float(y) / float(h);
    }
  }
  return image;
}

// Deterministic noise of amplitude a in [−a, a] (a linear congruential generator).
RgbImage with_noise(RgbImage image, float amplitude) {
  uint32_t state = 12345;
  for (float& v : image.rgb) {
    state = state * 1664525u + 1013904223u;
    v += amplitude * (2.0f * float(state >> 8) / float(1u << 24) - 1.0f);
  }
  return image;
}

double rec709(float r, float g, float b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

TEST(ErrorMetrics, IdenticalImagesHaveNoError) {
  const RgbImage image = textured(48, 32);
  const ErrorMetrics m = measure_error(image, image);
  EXPECT_EQ(m.compared_pixels, image.pixels());
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.relative_rmse, 0.0);
  EXPECT_EQ(m.max_abs_error, 0.0);
  EXPECT_EQ(m.relative_mean_error, 0.0);
  EXPECT_EQ(m.psnr_db, kInf);
  EXPECT_EQ(m.ssim, 1.0);
  EXPECT_EQ(m.flip, 0.0);
  EXPECT_EQ(m.nan_values + m.inf_values, 0u);
}

TEST(ErrorMetrics, ConstantOffsetOnAConstantImage) {
  // 0.75 − 0.5 = 0.25 in every channel: exact in float.
  const ErrorMetrics m = measure_error(constant(32, 24, {0.75f, 0.75f, 0.75f}), constant(32, 24, {0.5f, 0.5f, 0.5f}));
  EXPECT_EQ(m.rmse, 0.25);
  EXPECT_EQ(m.relative_rmse, 0.5);
  EXPECT_EQ(m.max_abs_error, 0.25);
  EXPECT_EQ(m.relative_mean_error, 0.5);
  EXPECT_DOUBLE_EQ(m.psnr_db, 20.0 * std::log10(0.5 / 0.25));
  // Constant images: the variances are 0 and SSIM is the luminance term (2μxμy + C₁)/(μx² + μy² + C₁), C₁ = (0.01 peak)².
  const double mx = rec709(0.75f, 0.75f, 0.75f), my = rec709(0.5f, 0.5f, 0.5f), c1 = (0.01 * 0.5) * (0.01 * 0.5);
  EXPECT_NEAR(m.ssim, (2 * mx * my + c1) / (mx * mx + my * my + c1), 1e-12);
  EXPECT_GT(m.flip, 0.0);
}

TEST(ErrorMetrics, ConstantOffsetOfAColour) {
  // An offset c = 0.1 on (0.3, 0.6, 0.2): exact to float rounding of the stored values (~3e-8).
  const ErrorMetrics m = measure_error(constant(16, 16, {0.4f, 0.7f, 0.3f}), constant(16, 16, {0.3f, 0.6f, 0.2f}));
  const double rms_reference = std::sqrt((0.3 * 0.3 + 0.6 * 0.6 + 0.2 * 0.2) / 3);
  EXPECT_NEAR(m.rmse, 0.1, 1e-7);
  EXPECT_NEAR(m.max_abs_error, 0.1, 1e-7);
  EXPECT_NEAR(m.relative_rmse, 0.1 / rms_reference, 1e-6);
  EXPECT_NEAR(m.relative_mean_error, 0.3 / 1.1, 1e-6);
  EXPECT_NEAR(m.psnr_db, 20.0 * std::log10(0.6 / 0.1), 1e-5);
}

TEST(ErrorMetrics, SsimIsOneForItselfAndDropsWithNoise) {
  const RgbImage reference = textured(48, 32);
  const double light = measure_error(with_noise(reference, 0.05f), reference).ssim;
  const double heavy = measure_error(with_noise(reference, 0.5f), reference).ssim;
  EXPECT_EQ(measure_error(reference, reference).ssim, 1.0);
  EXPECT_LT(light, 1.0);
  EXPECT_LT(heavy, light);
  EXPECT_GT(heavy, -1.0);
}

TEST(Ssim, AStepFollowsEquation13ByHand) {
  // Grey vertical steps, constant along y: the 11x11 window reduces to its 1-D Gaussian
  // (σ = 1.5) along x, cut at the image's edges and renormalised; then Wang et al. 2004
  // eq. 13 with C₁ = (0.01 L)², C₂ = (0.03 L)². Tolerance 1e-10: the cancellation in σ² = E[x²] − μ².
  const uint32_t w = 24, h = 7;
  const double range = 0.8;
  std::vector<double> test(size_t(w) * h), reference(size_t(w) * h);
  for (size_t p = 0; p < test.size(); ++p) {
    const bool right = p % w >= 10;
    test[p] = right ? 0.6 : 0.2;
    reference[p] = right ? 0.8 : 0.2 + 0.01 * double(p % w);
  }
  const std::vector<double> map = ssim_map(test, reference, w, h, range);
  const double c1 = 0.0001 * range * range, c2 = 0.0009 * range * range;
  for (int x = 0; x < int(w); ++x) {
    double weight = 0, mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
    for (int j = std::max(0, x - 5); j <= std::min(int(w) - 1, x + 5); ++j) {
      const double g = std::exp(-double((j - x) * (j - x)) / (2 * 1.5 * 1.5)), a = test[j], b = reference[j];
      weight += g, mx += g * a, my += g * b, xx += g * a * a, yy += g * b * b, xy += g * a * b;
    }
    mx /= weight, my /= weight, xx /= weight, yy /= weight, xy /= weight;
    const double expected = (2 * mx * my + c1) * (2 * (xy - mx * my) + c2) /
                            ((mx * mx + my * my + c1) * (xx - mx * mx + yy - my * my + c2));
    for (uint32_t y = 0; y < h; ++y) ASSERT_NEAR(map[y * w + x], expected, 1e-10) << "x " << x << ", y " << y;
  }
}

TEST(ErrorMetrics, AMaskRestrictsEveryFigure) {
  // The test differs only at x ≥ 64, the mask is x < 32: farther than every window
  // (SSIM 5 pixels, FLIP's filters 10 at 67 pixels a degree), so inside it nothing differs.
  const uint32_t w = 96, h = 32;
  const RgbImage reference = textured(w, h);
  RgbImage test = reference;
  PixelMask left(size_t(w) * h, false), right(size_t(w) * h, false);
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const size_t p = size_t(y) * w + x;
      left[p] = x < 32;
      right[p] = x >= 64;
      if (x >= 64) {
        for (size_t c = 0; c < 3; ++c) test.rgb[3 * p + c] += 0.5f;
      }
    }
  }
  const ErrorMetrics inside = measure_error(test, reference, left);
  EXPECT_EQ(inside.compared_pixels, 32u * h);
  EXPECT_EQ(inside.rmse, 0.0);
  EXPECT_EQ(inside.max_abs_error, 0.0);
  EXPECT_EQ(inside.relative_mean_error, 0.0);
  EXPECT_EQ(inside.psnr_db, kInf);
  EXPECT_EQ(inside.ssim, 1.0);
  EXPECT_EQ(inside.flip, 0.0);
  const ErrorMetrics outside = measure_error(test, reference, right);
  EXPECT_NEAR(outside.rmse, 0.5, 1e-6);
  EXPECT_NEAR(outside.max_abs_error, 0.5, 1e-6);
  EXPECT_LT(outside.ssim, 1.0);
  EXPECT_GT(outside.flip, 0.0);
  EXPECT_NEAR(measure_error(test, reference).rmse, 0.5 * std::sqrt(32.0 / 96.0), 1e-6);
}

TEST(ErrorMetrics, NonFiniteTestValuesAreCountedAndLeftOut) {
  const uint32_t w = 16, h = 12;
  const RgbImage reference = constant(w, h, {0.5f, 0.5f, 0.5f});
  RgbImage test = constant(w, h, {0.75f, 0.75f, 0.75f});
  test.rgb[3 * 5 + 0] = kNaN;
  test.rgb[3 * 5 + 2] = kNaN;
  test.rgb[3 * 40 + 1] = std::numeric_limits<float>::infinity();
  test.rgb[3 * 41 + 0] = -std::numeric_limits<float>::infinity();
  test.rgb[3 * 100 + 0] = kNaN;  // outside the mask below
  PixelMask mask(size_t(w) * h, true);
  mask[100] = false;
  const ErrorMetrics m = measure_error(test, reference, mask);
  EXPECT_EQ(m.nan_values, 2u);
  EXPECT_EQ(m.inf_values, 2u);
  EXPECT_EQ(m.compared_pixels, size_t(w) * h - 4);
  EXPECT_EQ(m.rmse, 0.25);
  EXPECT_EQ(m.max_abs_error, 0.25);
  EXPECT_TRUE(std::isfinite(m.ssim));
  EXPECT_TRUE(std::isfinite(m.flip));
  // Non-finite values in an otherwise identical image: the rest agrees exactly.
  RgbImage same = reference;
  same.rgb[3 * 7 + 1] = kNaN;
  const ErrorMetrics n = measure_error(same, reference);
  EXPECT_EQ(n.nan_values, 1u);
  EXPECT_EQ(n.rmse, 0.0);
  EXPECT_EQ(n.ssim, 1.0);
  EXPECT_EQ(n.flip, 0.0);
}

TEST(ErrorMetrics, AbsErrorMapIsTheLargestChannelErrorAndInfinityWhereNotFinite) {
  RgbImage reference = constant(4, 2, {0.5f, 0.5f, 0.5f});
  RgbImage test = reference;
  test.rgb[3 * 1 + 2] = 0.125f;
  test.rgb[3 * 1 + 0] = 0.75f;
  test.rgb[3 * 6 + 1] = kNaN;
  const std::vector<float> map = abs_error_map(test, reference);
  ASSERT_EQ(map.size(), 8u);
  EXPECT_EQ(map[0], 0.0f);
  EXPECT_EQ(map[1], 0.375f);
  EXPECT_EQ(map[6], std::numeric_limits<float>::infinity());
}

TEST(ErrorMetrics, ABlackReferenceHasADynamicRangeOfOne) {
  const ErrorMetrics m = measure_error(constant(8, 8, {0.1f, 0.1f, 0.1f}), constant(8, 8, {0, 0, 0}));
  EXPECT_NEAR(m.psnr_db, 20.0, 1e-5);  // 20 log10(1 / 0.1)
  EXPECT_EQ(m.relative_rmse, kInf);
  EXPECT_EQ(m.relative_mean_error, kInf);
  EXPECT_TRUE(std::isfinite(m.ssim));
  const ErrorMetrics black = measure_error(constant(8, 8, {0, 0, 0}), constant(8, 8, {0, 0, 0}));
  EXPECT_EQ(black.relative_rmse, 0.0);
  EXPECT_EQ(black.relative_mean_error, 0.0);
  EXPECT_EQ(black.ssim, 1.0);
  EXPECT_EQ(black.flip, 0.0);
}

TEST(ErrorMetrics, AnEmptyMaskComparesNothing) {
  const ErrorMetrics m =
      measure_error(constant(8, 8, {1, 1, 1}), constant(8, 8, {0, 0, 0}), PixelMask(64, false));
  EXPECT_EQ(m.compared_pixels, 0u);
  EXPECT_TRUE(std::isnan(m.rmse));
  EXPECT_TRUE(std::isnan(m.psnr_db));
}

// No figure turns NaN into a perfect score: a reference (or test) with no finite pixel
// compares nothing, and every figure says so (NaN), never rel_rmse 0, PSNR inf, SSIM 1.
TEST(ErrorMetrics, NonFiniteImagesAreNeverAPerfectMatch) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const RgbImage good = constant(8, 8, {0.5f, 0.5f, 0.5f});
  for (const RgbImage& bad : {constant(8, 8, {nan, nan, nan}), constant(8, 8, {inf, inf, inf}), constant(8, 8, {nan, 0, -inf})}) {
    for (const ErrorMetrics& m : {measure_error(good, bad), measure_error(bad, good), measure_error(bad, bad)}) {
      EXPECT_EQ(m.compared_pixels, 0u);
      for (const std::string& name : metric_names()) {
        EXPECT_TRUE(std::isnan(metric_value(m, name))) << name << " = " << metric_value(m, name);
      }
    }
  }
}

TEST(ErrorMetrics, APrecomputedFlipMapGivesTheSameFigures) {
  const RgbImage reference = textured(32, 24), test = with_noise(reference, 0.1f);
  const ErrorMetrics direct = measure_error(test, reference);
  const ErrorMetrics shared = measure_error_with_flip_map(test, reference, {}, flip_hdr_map(test, reference));
  EXPECT_EQ(direct.flip, shared.flip);
  EXPECT_EQ(direct.ssim, shared.ssim);
  EXPECT_GT(direct.flip, 0.0);
  EXPECT_THROW(measure_error_with_flip_map(test, reference, {}, std::vector<float>(3)), std::invalid_argument);
}

TEST(ErrorMetrics, RejectsMismatchedSizes) {
  const RgbImage a = constant(8, 8, {0, 0, 0}), b = constant(8, 4, {0, 0, 0});
  EXPECT_THROW(measure_error(a, b), std::invalid_argument);
  EXPECT_THROW(measure_error(a, a, PixelMask(10, true)), std::invalid_argument);
  EXPECT_THROW(abs_error_map(a, b), std::invalid_argument);
}

TEST(MetricNames, EveryNameReadsItsFigureAndKnowsWhichWayIsBetter) {
  ErrorMetrics m;
  m.rmse = 1, m.relative_rmse = 2, m.psnr_db = 3, m.ssim = 0.5, m.flip = 0.25, m.max_abs_error = 6,
  m.relative_mean_error = 7;
  EXPECT_EQ(metric_names().size(), 7u);
  EXPECT_EQ(metric_value(m, "rmse"), 1);
  EXPECT_EQ(metric_value(m, "rel_rmse"), 2);
  EXPECT_EQ(metric_value(m, "psnr"), 3);
  EXPECT_EQ(metric_value(m, "ssim"), 0.5);
  EXPECT_EQ(metric_value(m, "flip"), 0.25);
  EXPECT_EQ(metric_value(m, "max_abs"), 6);
  EXPECT_EQ(metric_value(m, "rel_mean"), 7);
  for (const std::string& name : metric_names()) {
    EXPECT_TRUE(is_metric_name(name));
    EXPECT_EQ(metric_lower_is_better(name), name != "psnr" && name != "ssim") << name;
  }
  EXPECT_FALSE(is_metric_name("mse"));
  EXPECT_THROW(metric_value(m, "mse"), std::invalid_argument);
  EXPECT_THROW(metric_lower_is_better("mse"), std::invalid_argument);
}

}  // namespace
}  // namespace volgraph::compare
