// FLIP and HDR-FLIP (tools/compare/flip.h) against answers worked out here from the
// papers' equations (Andersson et al. 2020, 2021): identical images, constant colours
// through the colour pipeline by hand, black against white, symmetry, growth with blur,
// the HDR exposures, invariance to a common scale, non-finite pixels.
#include "tools/compare/flip.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tests/compare/test_images.h"

namespace volgraph::compare {
namespace {

using test_images::box_blurred;
using test_images::checkerboard;
using test_images::constant;
using test_images::mean;

// ---- The colour pipeline by hand, for constant images (no features: ΔE = ΔE_c). ----

struct Lab {
  double l, a, b;
};

double srgb_decoded(double s) { return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4); }

// Linear sRGB to CIE L*a*b* (D65), the IEC 61966-2-1 matrix to four decimals and CIE 1976 L*a*b*.
Lab lab_of_linear(std::array<double, 3> rgb) {
  const double x = 0.4124 * rgb[0] + 0.3576 * rgb[1] + 0.1805 * rgb[2];
  const double y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
  const double z = 0.0193 * rgb[0] + 0.1192 * rgb[1] + 0.9505 * rgb[2];
  const double xn = 0.4124 + 0.3576 + 0.1805, yn = 1.0, zn = 0.0193 + 0.1192 + 0.9505;
  auto f = [](double t) { return t > std::pow(6.0 / 29.0, 3) ? std::cbrt(t) : t / (3 * std::pow(6.0 / 29.0, 2)) + 4.0 / 29.0; };
  return {116 * f(y / yn) - 16, 500 * (f(x / xn) - f(y / yn)), 200 * (f(y / yn) - f(z / zn))};
}

// HyAB of the Hunt-adjusted colours (a, b scaled by L/100).
double hunt_hyab(Lab p, Lab q) {
  const double da = 0.01 * p.l * p.a - 0.01 * q.l * q.a, db = 0.01 * p.l * p.b - 0.01 * q.l * q.b;
  return std::fabs(p.l - q.l) + std::sqrt(da * da + db * db);
}

// ΔE_c: HyAB^0.7 remapped with c_max (green against blue), p_c = 0.4, p_t = 0.95.
double colour_error(Lab p, Lab q) {
  const double cmax = std::pow(hunt_hyab(lab_of_linear({0, 1, 0}), lab_of_linear({0, 0, 1})), 0.7);
  const double d = std::pow(hunt_hyab(p, q), 0.7), knee = 0.4 * cmax;
  return d < knee ? 0.95 * d / knee : 0.95 + 0.05 * (d - knee) / (cmax - knee);
}

double colour_error_of_srgb(std::array<double, 3> test, std::array<double, 3> reference) {
  auto lab = [](std::array<double, 3> s) {
    return lab_of_linear({srgb_decoded(s[0]), srgb_decoded(s[1]), srgb_decoded(s[2])});
  };
  return colour_error(lab(test), lab(reference));
}

// A smooth HDR image with texture: a gradient times a checkerboard, values 0.05 … 20.
RgbImage hdr_texture(uint32_t w, uint32_t h) {
  RgbImage image = checkerboard(w, h, 6, 0.3f, 1.0f);
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const float gain = 0.15f + 19.85f * float(x) / float(w - 1);
      float* p = &image.rgb[3 * (size_t(y) * w + x)];
      p[0] *= gain, p[1] *= gain * 0.8f, p[2] *= gain * (0.5f + 0.5f * float(y) / float(h));
    }
  }
  return image;
}

TEST(FlipLdr, IdenticalImagesAreZeroEverywhere) {
  const RgbImage image = checkerboard(48, 32, 5, 0.1f, 0.9f);
  for (float e : flip_ldr_map(image, image)) ASSERT_EQ(e, 0.0f);
}

TEST(FlipHdr, IdenticalImagesAreZeroEverywhere) {
  const RgbImage image = hdr_texture(48, 32);
  for (float e : flip_hdr_map(image, image)) ASSERT_EQ(e, 0.0f);
}

TEST(FlipLdr, ConstantColoursFollowTheColourPipelineByHand) {
  // Two constant images: the filters keep the colours, the feature terms are 0, so every
  // pixel is ΔE_c of the two colours. Tolerance 1e-4 absolute: float filtering and the
  // four-decimal matrix here against the exact one in flip.cpp.
  const std::array<double, 3> test{0.7, 0.3, 0.1}, reference{0.2, 0.5, 0.8};
  const double expected = colour_error_of_srgb(test, reference);
  const std::vector<float> map = flip_ldr_map(constant(24, 16, {0.7f, 0.3f, 0.1f}), constant(24, 16, {0.2f, 0.5f, 0.8f}));
  for (float e : map) ASSERT_NEAR(e, expected, 1e-4);
  const double near_expected = colour_error_of_srgb({0.52, 0.5, 0.5}, {0.5, 0.5, 0.5});  // below the knee p_c c_max
  for (float e : flip_ldr_map(constant(24, 16, {0.52f, 0.5f, 0.5f}), constant(24, 16, {0.5f, 0.5f, 0.5f}))) {
    ASSERT_NEAR(e, near_expected, 1e-4);
  }
  EXPECT_LT(near_expected, 0.95);
  EXPECT_GT(expected, near_expected);
}

TEST(FlipLdr, BlackAgainstWhiteIsNearlyOne) {
  // HyAB(black, white) = 100 (lightness only): 100^0.7 = 25.1 lies above p_c c_max, so
  // ΔE = 0.95 + 0.05 (25.1 − 0.4 c_max) / (0.6 c_max) = 0.967 (c_max = 41.3).
  const double expected = colour_error_of_srgb({0, 0, 0}, {1, 1, 1});
  EXPECT_NEAR(expected, 0.967, 0.001);
  for (float e : flip_ldr_map(constant(16, 16, {0, 0, 0}), constant(16, 16, {1, 1, 1}))) ASSERT_NEAR(e, expected, 1e-4);
}

TEST(FlipLdr, IsSymmetric) {
  const RgbImage a = checkerboard(40, 24, 4, 0.2f, 0.8f);
  const RgbImage b = box_blurred(a, 2);
  EXPECT_EQ(flip_ldr_map(a, b), flip_ldr_map(b, a));
}

TEST(FlipLdr, GrowsWithBlurRadius) {
  const RgbImage sharp = checkerboard(64, 48, 8, 0.1f, 0.9f);
  double previous = 0;
  for (int radius : {1, 2, 4}) {
    const double e = mean(flip_ldr_map(box_blurred(sharp, radius), sharp));
    RecordProperty("mean_flip_ldr_box_radius_" + std::to_string(radius), std::to_string(e));
    EXPECT_GT(e, previous) << "box radius " << radius;
    previous = e;
  }
}

TEST(FlipHdr, GrowsWithBlurRadius) {
  const RgbImage sharp = hdr_texture(64, 48);
  double previous = 0;
  for (int radius : {1, 2, 4}) {
    const double e = mean(flip_hdr_map(box_blurred(sharp, radius), sharp));
    RecordProperty("mean_flip_hdr_box_radius_" + std::to_string(radius), std::to_string(e));
    EXPECT_GT(e, previous) << "box radius " << radius;
    previous = e;
  }
}

// The value x with Narkowicz's ACES fit (x(2.51x + 0.03)) / (x(2.43x + 0.59) + 0.14) at 0.6x equal to t, by bisection.
double aces_inverse(double t) {
  auto aces = [](double x) {
    const double v = 0.6 * x;
    return v * (2.51 * v + 0.03) / (v * (2.43 * v + 0.59) + 0.14);
  };
  double lo = 0, hi = 100;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (aces(mid) < t ? lo : hi) = mid;
  }
  return lo;
}

RgbImage grey_row(const std::vector<float>& values) {
  RgbImage image = constant(uint32_t(values.size()), 1, {0, 0, 0});
  for (size_t p = 0; p < values.size(); ++p) {
    for (size_t c = 0; c < 3; ++c) image.rgb[3 * p + c] = values[p];
  }
  return image;
}

TEST(FlipHdr, ExposuresBringTheMaximumAndTheMedianTo085) {
  const double x85 = aces_inverse(0.85);
  EXPECT_NEAR(flip_aces_tonemap(x85), 0.85, 1e-12);
  // Grey pixels: the Rec. 709 luminance is the value. Sorted, the element at n/2 = 2 is 0.4.
  const FlipExposures e = flip_hdr_exposures(grey_row({3.0f, 0.1f, 0.4f, 0.2f, 0.8f}));
  EXPECT_TRUE(e.found);
  EXPECT_NEAR(e.start, std::log2(x85 / 3.0), 1e-6);
  EXPECT_NEAR(e.stop, std::log2(x85 / 0.4), 1e-6);
  EXPECT_EQ(e.count, 3);  // ⌈log2(3 / 0.4)⌉ = ⌈2.91⌉
  // More than half black: the median of the positive luminances (0.25, 0.5, 2 → 0.5).
  const FlipExposures dark = flip_hdr_exposures(grey_row({0, 0, 2.0f, 0, 0.25f, 0, 0.5f}));
  EXPECT_NEAR(dark.stop, std::log2(x85 / 0.5), 1e-6);
  EXPECT_NEAR(dark.start, std::log2(x85 / 2.0), 1e-6);
  EXPECT_EQ(dark.count, 2);
  EXPECT_FALSE(flip_hdr_exposures(grey_row({0, 0, 0})).found);
}

TEST(FlipHdr, InvariantToScalingBothImagesByOneFactor) {
  // The exposures follow the reference's luminance, so scaling both images by k shifts
  // them by −log2 k and every tone-mapped image stays the same. Tolerance 1e-4 a pixel:
  // float rounding of the scaled values.
  const RgbImage reference = hdr_texture(48, 32);
  const RgbImage test = box_blurred(reference, 1);
  const std::vector<float> base = flip_hdr_map(test, reference);
  for (float k : {4.0f, 0.001f, 37.5f}) {
    RgbImage t = test, r = reference;
    for (float& v : t.rgb) v *= k;
    for (float& v : r.rgb) v *= k;
    const std::vector<float> scaled = flip_hdr_map(t, r);
    for (size_t p = 0; p < base.size(); ++p) ASSERT_NEAR(scaled[p], base[p], 1e-4) << "scale " << k << ", pixel " << p;
  }
  EXPECT_GT(mean(base), 0.0);
}

TEST(FlipHdr, NonFinitePixelsAreInfiniteAndSpareTheirNeighbours) {
  const RgbImage reference = hdr_texture(32, 24);
  RgbImage test = reference;
  test.rgb[3 * 100 + 1] = std::numeric_limits<float>::quiet_NaN();
  test.rgb[3 * 200] = std::numeric_limits<float>::infinity();
  const std::vector<float> map = flip_hdr_map(test, reference);
  for (size_t p = 0; p < map.size(); ++p) {
    if (p == 100 || p == 200) {
      EXPECT_EQ(map[p], std::numeric_limits<float>::infinity());
    } else {
      ASSERT_EQ(map[p], 0.0f) << "pixel " << p;
    }
  }
}

TEST(Flip, RejectsMismatchedSizesAndBadViewingDistance) {
  const RgbImage a = constant(8, 8, {0.5f, 0.5f, 0.5f}), b = constant(8, 9, {0.5f, 0.5f, 0.5f});
  EXPECT_THROW(flip_ldr_map(a, b), std::invalid_argument);
  EXPECT_THROW(flip_hdr_map(a, b), std::invalid_argument);
  EXPECT_THROW(flip_hdr_map(a, a, 0.0), std::invalid_argument);
  EXPECT_THROW(flip_ldr_map(a, a, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace volgraph::compare
