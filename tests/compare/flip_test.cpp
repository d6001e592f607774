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

// The 1-D kernels of the two pipelines at 67 pixels a degree, from the paper's formulas.
std::vector<double> normalised(std::vector<double> k) {
  double sum = 0;
  for (double v : k) sum += v;
  for (double& v : k) v /= sum;
  return k;
}

std::vector<double> signed_normalised(std::vector<double> k) {
  double positive = 0, negative = 0;
  for (double v : k) (v > 0 ? positive : negative) += std::fabs(v);
  for (double& v : k) v /= v > 0 ? positive : negative;
  return k;
}

constexpr double kPi = 3.14159265358979323846;

// One channel's contrast sensitivity in the spatial domain (Andersson et al. 2020):
// s(x, y) = a₁ √(π/b₁) e^(−π²(x²+y²)/b₁) + a₂ √(π/b₂) e^(−π²(x²+y²)/b₂), x, y = i/ppd
// degrees, over the square of radius ⌈3 √(0.04 / 2π²) ppd⌉ = 10, normalised to sum 1;
// here summed over y, as an image constant along y sees it.
std::vector<double> csf_row_kernel(double a1, double b1, double a2, double b2, double ppd) {
  const int r = int(std::ceil(3 * std::sqrt(0.04 / (2 * kPi * kPi)) * ppd));
  std::vector<double> k(size_t(2 * r + 1), 0.0);
  for (int i = -r; i <= r; ++i) {
    for (int j = -r; j <= r; ++j) {
      const double d2 = (double(i) * i + double(j) * j) / (ppd * ppd);
      k[i + r] += a1 * std::sqrt(kPi / b1) * std::exp(-kPi * kPi * d2 / b1) +
                  a2 * std::sqrt(kPi / b2) * std::exp(-kPi * kPi * d2 / b2);
    }
  }
  return normalised(k);
}

struct FeatureKernels {
  std::vector<double> dg, ddg;
};

// σ = ½ · 0.082 · ppd, radius ⌈3σ⌉: −x g and (x²/σ² − 1) g, each side summing to ±1.
FeatureKernels feature_kernels(double ppd) {
  const double sigma = 0.5 * 0.082 * ppd;
  const int r = int(std::ceil(3 * sigma));
  FeatureKernels k;
  for (int i = -r; i <= r; ++i) {
    const double g = std::exp(-double(i * i) / (2 * sigma * sigma));
    k.dg.push_back(-i * g);
    k.ddg.push_back((double(i * i) / (sigma * sigma) - 1) * g);
  }
  return {signed_normalised(k.dg), signed_normalised(k.ddg)};
}

// Σ_j k(j) v(clamp(x + j)) along one row.
double filtered_at(const std::vector<double>& row, const std::vector<double>& k, int x) {
  const int r = int(k.size() / 2), w = int(row.size());
  double sum = 0;
  for (int j = -r; j <= r; ++j) sum += k[j + r] * row[std::clamp(x + j, 0, w - 1)];
  return sum;
}

using Rgb = std::array<double, 3>;

// Linear sRGB ↔ XYZ (the four-decimal matrix and its numerical inverse), D65 white of RGB (1, 1, 1).
constexpr double kM[3][3] = {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
Rgb xyz_of(Rgb c) {
  return {kM[0][0] * c[0] + kM[0][1] * c[1] + kM[0][2] * c[2], kM[1][0] * c[0] + kM[1][1] * c[1] + kM[1][2] * c[2],
          kM[2][0] * c[0] + kM[2][1] * c[1] + kM[2][2] * c[2]};
}
Rgb rgb_of_xyz(Rgb v) {
  const double det = kM[0][0] * (kM[1][1] * kM[2][2] - kM[1][2] * kM[2][1]) -
                     kM[0][1] * (kM[1][0] * kM[2][2] - kM[1][2] * kM[2][0]) +
                     kM[0][2] * (kM[1][0] * kM[2][1] - kM[1][1] * kM[2][0]);
  auto column_replaced = [&](int col) {  // Cramer's rule
    double m[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] = j == col ? v[i] : kM[i][j];
    }
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) / det;
  };
  return {column_replaced(0), column_replaced(1), column_replaced(2)};
}
const Rgb kWhiteXyz = xyz_of({1, 1, 1});

// YCxCz: Y = 116 Y/Yn − 16, Cx = 500 (X/Xn − Y/Yn), Cz = 200 (Y/Yn − Z/Zn).
Rgb ycxcz_of_linear(Rgb c) {
  const Rgb v = xyz_of(c);
  const double x = v[0] / kWhiteXyz[0], y = v[1] / kWhiteXyz[1], z = v[2] / kWhiteXyz[2];
  return {116 * y - 16, 500 * (x - y), 200 * (y - z)};
}
Rgb linear_of_ycxcz(Rgb o) {
  const double y = (o[0] + 16) / 116;
  return rgb_of_xyz({(y + o[1] / 500) * kWhiteXyz[0], y * kWhiteXyz[1], (y - o[2] / 200) * kWhiteXyz[2]});
}

RgbImage step_image(uint32_t w, uint32_t h, Rgb left, Rgb right) {
  RgbImage image = constant(w, h, {0, 0, 0});
  for (size_t p = 0; p < image.pixels(); ++p) {
    const Rgb& c = p % w < w / 2 ? left : right;
    for (size_t i = 0; i < 3; ++i) image.rgb[3 * p + i] = float(c[i]);
  }
  return image;
}

// LDR-FLIP across a vertical step (sRGB `left` → `right`), worked out here: nothing
// changes along y, so each pipeline is a 1-D filter of the row. Colour: each YCxCz
// channel through its CSF, back to linear RGB clamped to [0, 1], Hunt-adjusted L*a*b*,
// HyAB^0.7 remapped; features: |Σ dg Y| and |Σ ddg Y| of the luminance; ΔE = ΔE_c^(1 − ΔE_f).
void expect_step_by_hand(Rgb left, Rgb test_right, Rgb reference_right) {
  const uint32_t w = 64, h = 12;
  const double ppd = kFlipPixelsPerDegree;
  const std::array<std::vector<double>, 3> csf{csf_row_kernel(1, 0.0047, 0, 1e-5, ppd),
                                               csf_row_kernel(1, 0.0053, 0, 1e-5, ppd),
                                               csf_row_kernel(34.1, 0.04, 13.5, 0.025, ppd)};
  const FeatureKernels features = feature_kernels(ppd);
  const double cmax = std::pow(hunt_hyab(lab_of_linear({0, 1, 0}), lab_of_linear({0, 0, 1})), 0.7);
  struct Rows {
    std::array<std::vector<double>, 3> opponent;
    std::vector<double> luminance;
  };
  auto rows_of = [&](Rgb right) {
    Rows rows;
    for (uint32_t x = 0; x < w; ++x) {
      const Rgb s = x < w / 2 ? left : right;
      const Rgb linear{srgb_decoded(s[0]), srgb_decoded(s[1]), srgb_decoded(s[2])};
      const Rgb o = ycxcz_of_linear(linear);
      for (size_t c = 0; c < 3; ++c) rows.opponent[c].push_back(o[c]);
      rows.luminance.push_back(xyz_of(linear)[1] / kWhiteXyz[1]);
    }
    return rows;
  };
  auto lab_at = [&](const Rows& rows, int x) {
    Rgb o;
    for (size_t c = 0; c < 3; ++c) o[c] = filtered_at(rows.opponent[c], csf[c], x);
    Rgb linear = linear_of_ycxcz(o);
    for (double& v : linear) v = std::clamp(v, 0.0, 1.0);
    return lab_of_linear(linear);
  };
  const Rows t = rows_of(test_right), r = rows_of(reference_right);
  const std::vector<float> map = flip_ldr_map(step_image(w, h, left, test_right), step_image(w, h, left, reference_right), ppd);
  for (int x = 16; x < 48; ++x) {
    const double d = std::pow(hunt_hyab(lab_at(t, x), lab_at(r, x)), 0.7), knee = 0.4 * cmax;
    const double colour = d < knee ? 0.95 * d / knee : 0.95 + 0.05 * (d - knee) / (cmax - knee);
    auto magnitude = [&](const Rows& rows, const std::vector<double>& k) { return std::fabs(filtered_at(rows.luminance, k, x)); };
    const double edge = std::fabs(magnitude(t, features.dg) - magnitude(r, features.dg));
    const double point = std::fabs(magnitude(t, features.ddg) - magnitude(r, features.ddg));
    const double feature = std::sqrt(std::max(edge, point) / std::sqrt(2.0));
    const double expected = std::pow(colour, 1 - feature);
    for (uint32_t y = 0; y < h; ++y) ASSERT_NEAR(map[y * w + x], expected, 2e-4) << "x " << x << ", y " << y;
  }
  EXPECT_GT(map[h / 2 * w + w / 2], map[h / 2 * w + 16]);  // the step stands out
}

TEST(FlipLdr, AGreyStepFollowsBothPipelinesByHand) {
  // Tolerance 2e-4 absolute: float filtering in flip.cpp, the four-decimal matrix here.
  expect_step_by_hand({0.2, 0.2, 0.2}, {0.6, 0.6, 0.6}, {0.8, 0.8, 0.8});
}

TEST(FlipLdr, AColourStepFollowsBothPipelinesByHand) {
  // Red–green and blue–yellow through their own CSFs (the blue–yellow one a sum of two Gaussians).
  expect_step_by_hand({0.8, 0.3, 0.1}, {0.2, 0.6, 0.3}, {0.1, 0.3, 0.9});
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

TEST(FlipHdr, ABlackReferenceTakesItsExposuresFromTheTest) {
  // The reference has no luminance to place the exposures; the test's (constant 0.01)
  // puts it at 0.85 after the tone mapper, against black: ΔE_c of linear 0.85 grey and black.
  const std::vector<float> map = flip_hdr_map(constant(16, 12, {0.01f, 0.01f, 0.01f}), constant(16, 12, {0, 0, 0}));
  const double expected = colour_error(lab_of_linear({0.85, 0.85, 0.85}), lab_of_linear({0, 0, 0}));
  for (float e : map) ASSERT_NEAR(e, expected, 1e-4);
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

void expect_infinite_only_at_100_and_200(const std::vector<float>& map) {
  for (size_t p = 0; p < map.size(); ++p) {
    if (p == 100 || p == 200) {
      EXPECT_EQ(map[p], std::numeric_limits<float>::infinity());
    } else {
      ASSERT_EQ(map[p], 0.0f) << "pixel " << p;
    }
  }
}

TEST(FlipHdr, NonFinitePixelsAreInfiniteAndSpareTheirNeighbours) {
  const RgbImage reference = hdr_texture(32, 24);
  RgbImage test = reference;
  test.rgb[3 * 100 + 1] = std::numeric_limits<float>::quiet_NaN();
  test.rgb[3 * 200] = std::numeric_limits<float>::infinity();
  expect_infinite_only_at_100_and_200(flip_hdr_map(test, reference));
}

TEST(FlipLdr, NonFinitePixelsAreInfiniteAndSpareTheirNeighbours) {
  const RgbImage reference = checkerboard(32, 24, 4, 0.2f, 0.7f);
  RgbImage test = reference;
  test.rgb[3 * 100 + 1] = std::numeric_limits<float>::quiet_NaN();
  test.rgb[3 * 200] = -std::numeric_limits<float>::infinity();
  expect_infinite_only_at_100_and_200(flip_ldr_map(test, reference));
}

// IEC 61966-2-1 encoding.
float srgb_encoded(double linear) {
  return float(linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055);
}

RgbImage tone_mapped_srgb(const RgbImage& linear, double exposure) {
  RgbImage out = linear;
  for (float& v : out.rgb) v = srgb_encoded(std::clamp(flip_aces_tonemap(std::exp2(exposure) * v), 0.0, 1.0));
  return out;
}

TEST(FlipHdr, IsTheLargestLdrFlipOverTheExposures) {
  // HDR-FLIP (Andersson et al. 2021): LDR-FLIP of the tone-mapped pair at each exposure,
  // the largest per pixel. Tolerance 1e-4 a pixel: the sRGB round trip of the LDR path.
  const RgbImage reference = hdr_texture(40, 24);
  const RgbImage test = box_blurred(reference, 1);
  const FlipExposures e = flip_hdr_exposures(reference);
  ASSERT_GE(e.count, 3);
  std::vector<float> largest(reference.pixels(), 0.0f);
  for (int i = 0; i < e.count; ++i) {
    const double exposure = e.start + i * (e.stop - e.start) / (e.count - 1);
    const std::vector<float> ldr = flip_ldr_map(tone_mapped_srgb(test, exposure), tone_mapped_srgb(reference, exposure));
    for (size_t p = 0; p < largest.size(); ++p) largest[p] = std::max(largest[p], ldr[p]);
  }
  const std::vector<float> hdr = flip_hdr_map(test, reference);
  for (size_t p = 0; p < hdr.size(); ++p) ASSERT_NEAR(hdr[p], largest[p], 1e-4) << "pixel " << p;
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
