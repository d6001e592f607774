// FLIP and HDR-FLIP (flip.h), written from Andersson et al. 2020 (HPG, "FLIP: A
// Difference Evaluator for Alternating Images") and Andersson et al. 2021 (Eurographics,
// "Visualizing Errors in Rendered High Dynamic Range Images"). The colour pipeline
// filters the opponent space YCxCz with the contrast sensitivity functions, compares in
// Hunt-adjusted L*a*b* with HyAB and remaps to [0, 1]; the feature pipeline compares
// edges and points of the luminance; the two combine as ΔE_c^(1 − ΔE_f).
#include "tools/compare/flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace volgraph::compare {
namespace {

constexpr double kPi = 3.14159265358979323846;

// FLIP's constants (Andersson et al. 2020): the colour-difference exponent q_c, the
// fraction p_c of c_max mapped to p_t, the feature exponent q_f and the feature width w
// (degrees: the edge/point detectors' σ = ½ w · ppd).
constexpr double kColourExponent = 0.7;
constexpr double kCmaxFraction = 0.4;
constexpr double kCmaxFractionError = 0.95;
constexpr double kFeatureExponent = 0.5;
constexpr double kFeatureWidthDegrees = 0.082;

// The contrast sensitivity functions in the spatial domain, one a channel of YCxCz
// (Andersson et al. 2020, colour pipeline): s(x) = a₁ √(π/b₁) e^(−π²x²/b₁) + a₂ √(π/b₂) e^(−π²x²/b₂),
// x in degrees. Achromatic and red–green have a₂ = 0; blue–yellow is a sum of two.
struct CsfGaussians {
  double a1, b1, a2, b2;
};
constexpr CsfGaussians kCsfAchromatic{1.0, 0.0047, 0.0, 1.0e-5};
constexpr CsfGaussians kCsfRedGreen{1.0, 0.0053, 0.0, 1.0e-5};
constexpr CsfGaussians kCsfBlueYellow{34.1, 0.04, 13.5, 0.025};

// ACES filmic fit (Narkowicz 2015) with FLIP's 0.6 pre-exposure: (c₀x² + c₁x + c₂) / (c₃x² + c₄x + c₅).
constexpr std::array<double, 6> kAces{0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.0, 0.6 * 0.6 * 2.43, 0.6 * 0.59, 0.14};
// HDR-FLIP's exposures bring the brightest reference pixel, or its median, to this tone-mapped value (Andersson et al. 2021).
constexpr double kExposureTarget = 0.85;

using Mat3 = std::array<std::array<double, 3>, 3>;

// Linear sRGB to CIE XYZ: the BT.709 primaries with the D65 white, in rational form.
constexpr Mat3 kRgbToXyz{{{10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
                          {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
                          {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}}};

constexpr Mat3 inverse(const Mat3& m) {
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  return {{{c00 / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det, (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det},
           {c01 / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det, (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det},
           {c02 / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det, (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det}}};
}
constexpr Mat3 kXyzToRgb = inverse(kRgbToXyz);

// The reference white: XYZ of linear RGB (1, 1, 1).
constexpr std::array<double, 3> kWhite{kRgbToXyz[0][0] + kRgbToXyz[0][1] + kRgbToXyz[0][2],
                                       kRgbToXyz[1][0] + kRgbToXyz[1][1] + kRgbToXyz[1][2],
                                       kRgbToXyz[2][0] + kRgbToXyz[2][1] + kRgbToXyz[2][2]};

struct Colour {
  float x, y, z;
};

// XYZ relative to the white, X/Xn, Y/Yn, Z/Zn.
Colour relative_to_white(Colour xyz) {
  return {xyz.x * float(1.0 / kWhite[0]), xyz.y * float(1.0 / kWhite[1]), xyz.z * float(1.0 / kWhite[2])};
}

Colour multiply(const Mat3& m, Colour c) {
  auto row = [&](size_t i) { return float(m[i][0]) * c.x + float(m[i][1]) * c.y + float(m[i][2]) * c.z; };
  return {row(0), row(1), row(2)};
}

// XYZ to the linearised opponent space YCxCz that FLIP filters in (Andersson et al. 2020).
Colour ycxcz_from_xyz(Colour xyz) {
  const Colour r = relative_to_white(xyz);
  return {116.0f * r.y - 16.0f, 500.0f * (r.x - r.y), 200.0f * (r.y - r.z)};
}

Colour xyz_from_ycxcz(Colour ycxcz) {
  const float yr = (ycxcz.x + 16.0f) / 116.0f;
  return {(yr + ycxcz.y / 500.0f) * float(kWhite[0]), yr * float(kWhite[1]), (yr - ycxcz.z / 200.0f) * float(kWhite[2])};
}

// CIE 1976 L*a*b*'s f(t).
float lab_f(float t) {
  constexpr float delta = 6.0f / 29.0f;
  if (t > delta * delta * delta) return std::cbrt(t);
  return t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

Colour lab_from_xyz(Colour xyz) {
  const Colour r = relative_to_white(xyz);
  const float fx = lab_f(r.x), fy = lab_f(r.y), fz = lab_f(r.z);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// The Hunt effect: chroma scaled by lightness, a' = 0.01 L a, b' = 0.01 L b (Andersson et al. 2020).
Colour hunt_adjusted(Colour lab) { return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z}; }

// HyAB (Abasi et al. 2020): city-block lightness plus Euclidean chroma distance.
float hyab(Colour a, Colour b) {
  const float da = a.y - b.y, db = a.z - b.z;
  return std::fabs(a.x - b.x) + std::sqrt(da * da + db * db);
}

Colour clamped01(Colour c) {
  return {std::clamp(c.x, 0.0f, 1.0f), std::clamp(c.y, 0.0f, 1.0f), std::clamp(c.z, 0.0f, 1.0f)};
}

// Linear RGB in [0, 1] to Hunt-adjusted L*a*b*.
Colour hunt_lab_from_linear(Colour rgb) { return hunt_adjusted(lab_from_xyz(multiply(kRgbToXyz, rgb))); }

// c_max: the colour difference between green and blue, raised to q_c (Andersson et al. 2020).
float max_colour_difference() {
  const double d = hyab(hunt_lab_from_linear({0, 1, 0}), hunt_lab_from_linear({0, 0, 1}));
  return float(std::pow(d, kColourExponent));
}

// ΔE_c: HyAB^q_c remapped so that [0, p_c c_max) covers [0, p_t) and [p_c c_max, c_max] covers [p_t, 1].
float remapped_colour_difference(float hyab_distance, float cmax) {
  const float d = std::pow(hyab_distance, float(kColourExponent));
  const float knee = float(kCmaxFraction) * cmax;
  if (d < knee) return d * float(kCmaxFractionError) / knee;
  return float(kCmaxFractionError) + (d - knee) / (cmax - knee) * (1.0f - float(kCmaxFractionError));
}

// A plane of floats, row-major.
struct Plane {
  uint32_t width = 0, height = 0;
  std::vector<float> v;
  Plane(uint32_t w, uint32_t h) : width(w), height(h), v(size_t(w) * h) {}
};

// A 1-D kernel of odd width 2·radius + 1.
using Kernel = std::vector<float>;

int radius_of(const Kernel& k) { return int(k.size() / 2); }

// A kernel whose weights sum to 0 (the derivatives) is applied as Σ_j k(j) (in(j) − in(0)):
// the same sum, but exactly 0 on a constant image rather than a rounding residual.
enum class KernelSum { one, zero };

// out(x, y) = Σ_j k(j) in(clamp(x + j), y): the horizontal half of a separable filter.
Plane filter_rows(const Plane& in, const Kernel& k, KernelSum kind = KernelSum::one) {
  const int r = radius_of(k), w = int(in.width);
  Plane out(in.width, in.height);
  std::vector<float> padded(size_t(w + 2 * r));
  for (uint32_t y = 0; y < in.height; ++y) {
    const float* row = &in.v[size_t(y) * w];
    for (int i = 0; i < w + 2 * r; ++i) padded[i] = row[std::clamp(i - r, 0, w - 1)];
    float* o = &out.v[size_t(y) * w];
    const float* centre = &padded[r];
    for (size_t j = 0; j < k.size(); ++j) {  // tap by tap: the loop over x vectorises
      const float weight = k[j];
      const float* tap = &padded[j];
      if (kind == KernelSum::zero) {
        for (int x = 0; x < w; ++x) o[x] += weight * (tap[x] - centre[x]);
      } else {
        for (int x = 0; x < w; ++x) o[x] += weight * tap[x];
      }
    }
  }
  return out;
}

// out(x, y) = Σ_j k(j) in(x, clamp(y + j)): the vertical half.
Plane filter_columns(const Plane& in, const Kernel& k, KernelSum kind = KernelSum::one) {
  const int r = radius_of(k), h = int(in.height);
  const size_t w = in.width;
  Plane out(in.width, in.height);
  for (int y = 0; y < h; ++y) {
    float* o = &out.v[y * w];
    const float* centre = &in.v[size_t(y) * w];
    for (int j = -r; j <= r; ++j) {
      const float weight = k[j + r];
      const float* row = &in.v[size_t(std::clamp(y + j, 0, h - 1)) * w];
      if (kind == KernelSum::zero) {
        for (size_t x = 0; x < w; ++x) o[x] += weight * (row[x] - centre[x]);
      } else {
        for (size_t x = 0; x < w; ++x) o[x] += weight * row[x];
      }
    }
  }
  return out;
}

Plane filter_separable(const Plane& in, const Kernel& horizontal, const Kernel& vertical) {
  return filter_columns(filter_rows(in, horizontal), vertical);
}

// The spatial filters of the colour pipeline, sampled at x = i / ppd degrees.
struct SpatialFilters {
  Kernel achromatic, red_green;            // each sums to 1
  Kernel blue_yellow_1, blue_yellow_2;     // k₁⊗k₁ + k₂⊗k₂ sums to 1
};

// The radius covers 3 standard deviations of the widest Gaussian: σ = √(b / 2π²) degrees.
int spatial_radius(double ppd) {
  const double widest_b = std::max({kCsfAchromatic.b1, kCsfRedGreen.b1, kCsfBlueYellow.b1, kCsfBlueYellow.b2});
  return int(std::ceil(3.0 * std::sqrt(widest_b / (2.0 * kPi * kPi)) * ppd));
}

double csf_gaussian(double x_degrees, double a, double b) {
  return a * std::sqrt(kPi / b) * std::exp(-kPi * kPi * x_degrees * x_degrees / b);
}

Kernel normalised(std::vector<double> k) {
  double sum = 0;
  for (double v : k) sum += v;
  Kernel out(k.size());
  for (size_t i = 0; i < k.size(); ++i) out[i] = float(k[i] / sum);
  return out;
}

SpatialFilters spatial_filters(double ppd) {
  const int r = spatial_radius(ppd);
  const size_t n = size_t(2 * r + 1);
  std::vector<double> y(n), cx(n), cz1(n), cz2(n);
  for (int i = -r; i <= r; ++i) {
    const double x = i / ppd;
    y[i + r] = csf_gaussian(x, kCsfAchromatic.a1, kCsfAchromatic.b1);
    cx[i + r] = csf_gaussian(x, kCsfRedGreen.a1, kCsfRedGreen.b1);
    // The 2-D Gaussian a√(π/b) e^(−π²(x²+y²)/b) is the outer product of √(a√(π/b)) e^(−π²x²/b) with itself.
    cz1[i + r] = std::sqrt(csf_gaussian(0, kCsfBlueYellow.a1, kCsfBlueYellow.b1)) *
                 std::exp(-kPi * kPi * x * x / kCsfBlueYellow.b1);
    cz2[i + r] = std::sqrt(csf_gaussian(0, kCsfBlueYellow.a2, kCsfBlueYellow.b2)) *
                 std::exp(-kPi * kPi * x * x / kCsfBlueYellow.b2);
  }
  double s1 = 0, s2 = 0;
  for (size_t i = 0; i < n; ++i) s1 += cz1[i], s2 += cz2[i];
  const double norm = 1.0 / std::sqrt(s1 * s1 + s2 * s2);  // the 2-D sum is s₁² + s₂²
  SpatialFilters f{normalised(y), normalised(cx), Kernel(n), Kernel(n)};
  for (size_t i = 0; i < n; ++i) f.blue_yellow_1[i] = float(cz1[i] * norm), f.blue_yellow_2[i] = float(cz2[i] * norm);
  return f;
}

// The edge and point detectors (Andersson et al. 2020, feature pipeline): a Gaussian of
// σ = ½ w ppd pixels, its first derivative −x g and second derivative (x²/σ² − 1) g; the
// Gaussian sums to 1, the derivatives' positive weights to 1 and negative ones to −1.
struct FeatureFilters {
  Kernel gaussian, first_derivative, second_derivative;
};

Kernel signed_normalised(const std::vector<double>& k) {
  double positive = 0, negative = 0;
  for (double v : k) (v > 0 ? positive : negative) += std::fabs(v);
  Kernel out(k.size());
  for (size_t i = 0; i < k.size(); ++i) {
    const double sum = k[i] > 0 ? positive : negative;
    out[i] = sum > 0 ? float(k[i] / sum) : 0.0f;
  }
  return out;
}

FeatureFilters feature_filters(double ppd) {
  const double sigma = 0.5 * kFeatureWidthDegrees * ppd;
  const int r = int(std::ceil(3.0 * sigma));
  const size_t n = size_t(2 * r + 1);
  std::vector<double> g(n), dg(n), ddg(n);
  for (int i = -r; i <= r; ++i) {
    const double x = i, gx = std::exp(-x * x / (2.0 * sigma * sigma));
    g[i + r] = gx;
    dg[i + r] = -x * gx;
    ddg[i + r] = (x * x / (sigma * sigma) - 1.0) * gx;
  }
  return {normalised(g), signed_normalised(dg), signed_normalised(ddg)};
}

struct Filters {
  SpatialFilters spatial;
  FeatureFilters feature;
  float cmax;
};

// A linear RGB image in [0, 1] as three planes.
struct LinearPlanes {
  std::array<Plane, 3> c;
  LinearPlanes(uint32_t w, uint32_t h) : c{Plane(w, h), Plane(w, h), Plane(w, h)} {}
};

// The colour pipeline's filtered image: YCxCz through the contrast sensitivity functions,
// back to linear RGB clamped to [0, 1], then Hunt-adjusted L*a*b* (Andersson et al. 2020).
std::array<Plane, 3> filtered_hunt_lab(const LinearPlanes& rgb, const SpatialFilters& f) {
  const uint32_t w = rgb.c[0].width, h = rgb.c[0].height;
  std::array<Plane, 3> opponent{Plane(w, h), Plane(w, h), Plane(w, h)};
  for (size_t i = 0; i < opponent[0].v.size(); ++i) {
    const Colour o = ycxcz_from_xyz(multiply(kRgbToXyz, {rgb.c[0].v[i], rgb.c[1].v[i], rgb.c[2].v[i]}));
    opponent[0].v[i] = o.x, opponent[1].v[i] = o.y, opponent[2].v[i] = o.z;
  }
  const Plane y = filter_separable(opponent[0], f.achromatic, f.achromatic);
  const Plane cx = filter_separable(opponent[1], f.red_green, f.red_green);
  const Plane cz1 = filter_separable(opponent[2], f.blue_yellow_1, f.blue_yellow_1);
  const Plane cz2 = filter_separable(opponent[2], f.blue_yellow_2, f.blue_yellow_2);
  std::array<Plane, 3> lab{Plane(w, h), Plane(w, h), Plane(w, h)};
  for (size_t i = 0; i < y.v.size(); ++i) {
    const Colour linear = clamped01(multiply(kXyzToRgb, xyz_from_ycxcz({y.v[i], cx.v[i], cz1.v[i] + cz2.v[i]})));
    const Colour l = hunt_lab_from_linear(linear);
    lab[0].v[i] = l.x, lab[1].v[i] = l.y, lab[2].v[i] = l.z;
  }
  return lab;
}

// Edge and point magnitudes of the luminance Y/Y_n (Andersson et al. 2020, feature
// pipeline): |(∂x, ∂y)| and |(∂xx, ∂yy)| of the Gaussian-filtered luminance.
struct Features {
  Plane edge, point;
};

Features features(const LinearPlanes& rgb, const FeatureFilters& f) {
  const uint32_t w = rgb.c[0].width, h = rgb.c[0].height;
  Plane luminance(w, h);
  for (size_t i = 0; i < luminance.v.size(); ++i) {
    luminance.v[i] = float((kRgbToXyz[1][0] * rgb.c[0].v[i] + kRgbToXyz[1][1] * rgb.c[1].v[i] +
                            kRgbToXyz[1][2] * rgb.c[2].v[i]) / kWhite[1]);
  }
  constexpr KernelSum zero = KernelSum::zero;
  const Plane smooth_x = filter_rows(luminance, f.gaussian);
  const Plane dx = filter_columns(filter_rows(luminance, f.first_derivative, zero), f.gaussian);
  const Plane dxx = filter_columns(filter_rows(luminance, f.second_derivative, zero), f.gaussian);
  const Plane dy = filter_columns(smooth_x, f.first_derivative, zero);
  const Plane dyy = filter_columns(smooth_x, f.second_derivative, zero);
  Features out{Plane(w, h), Plane(w, h)};
  for (size_t i = 0; i < luminance.v.size(); ++i) {
    out.edge.v[i] = std::sqrt(dx.v[i] * dx.v[i] + dy.v[i] * dy.v[i]);
    out.point.v[i] = std::sqrt(dxx.v[i] * dxx.v[i] + dyy.v[i] * dyy.v[i]);
  }
  return out;
}

// LDR-FLIP of two linear RGB images in [0, 1].
std::vector<float> flip_of_linear(const LinearPlanes& test, const LinearPlanes& reference, const Filters& f) {
  const std::array<Plane, 3> lab_t = filtered_hunt_lab(test, f.spatial), lab_r = filtered_hunt_lab(reference, f.spatial);
  const Features feat_t = features(test, f.feature), feat_r = features(reference, f.feature);
  const float inv_sqrt2 = float(1.0 / std::sqrt(2.0));
  std::vector<float> out(lab_t[0].v.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const float colour = remapped_colour_difference(
        hyab({lab_t[0].v[i], lab_t[1].v[i], lab_t[2].v[i]}, {lab_r[0].v[i], lab_r[1].v[i], lab_r[2].v[i]}), f.cmax);
    const float edge = std::fabs(feat_t.edge.v[i] - feat_r.edge.v[i]);
    const float point = std::fabs(feat_t.point.v[i] - feat_r.point.v[i]);
    // ΔE_f = (max(edge, point difference) / √2)^q_f
    const float feature = std::pow(inv_sqrt2 * std::max(edge, point), float(kFeatureExponent));
    out[i] = std::pow(colour, 1.0f - feature);  // ΔE = ΔE_c^(1 − ΔE_f)
  }
  return out;
}

Filters filters_for(double ppd) { return {spatial_filters(ppd), feature_filters(ppd), max_colour_difference()}; }

bool finite_pixel(const RgbImage& image, size_t p) {
  return std::isfinite(image.rgb[3 * p]) && std::isfinite(image.rgb[3 * p + 1]) && std::isfinite(image.rgb[3 * p + 2]);
}

void check_inputs(const RgbImage& test, const RgbImage& reference, double ppd) {
  if (test.width != reference.width || test.height != reference.height) {
    throw std::invalid_argument("FLIP: the test image is " + std::to_string(test.width) + "x" +
                                std::to_string(test.height) + ", the reference " + std::to_string(reference.width) +
                                "x" + std::to_string(reference.height));
  }
  if (test.rgb.size() != 3 * test.pixels() || reference.rgb.size() != 3 * reference.pixels()) {
    throw std::invalid_argument("FLIP: an image does not hold 3 floats a pixel");
  }
  if (!(ppd > 0) || !std::isfinite(ppd)) {
    throw std::invalid_argument("FLIP: pixels per degree must be a positive number, not " + std::to_string(ppd));
  }
}

// The two images with every pixel that is not finite in either replaced: the test takes
// the reference's value (both 0 where the reference is not finite); `bad` marks them.
struct FiniteInputs {
  RgbImage test, reference;
  std::vector<bool> bad;
};

FiniteInputs finite_inputs(const RgbImage& test, const RgbImage& reference) {
  FiniteInputs in{test, reference, std::vector<bool>(test.pixels(), false)};
  for (size_t p = 0; p < test.pixels(); ++p) {
    if (finite_pixel(test, p) && finite_pixel(reference, p)) continue;
    in.bad[p] = true;
    const bool reference_finite = finite_pixel(reference, p);
    for (size_t c = 0; c < 3; ++c) {
      const float value = reference_finite ? reference.rgb[3 * p + c] : 0.0f;
      in.test.rgb[3 * p + c] = value;
      in.reference.rgb[3 * p + c] = value;
    }
  }
  return in;
}

void mark_bad(std::vector<float>& map, const std::vector<bool>& bad) {
  for (size_t p = 0; p < map.size(); ++p) {
    if (bad[p]) map[p] = std::numeric_limits<float>::infinity();
  }
}

// IEC 61966-2-1 decoding.
float linear_from_srgb(float s) {
  if (s <= 0.04045f) return s / 12.92f;
  return std::pow((s + 0.055f) / 1.055f, 2.4f);
}

LinearPlanes linear_from_srgb_image(const RgbImage& srgb) {
  LinearPlanes out(srgb.width, srgb.height);
  for (size_t p = 0; p < srgb.pixels(); ++p) {
    for (size_t c = 0; c < 3; ++c) out.c[c].v[p] = linear_from_srgb(std::clamp(srgb.rgb[3 * p + c], 0.0f, 1.0f));
  }
  return out;
}

// The image at exposure 2^e through the ACES curve, clamped to [0, 1] (Andersson et al. 2021).
LinearPlanes tone_mapped(const RgbImage& linear, double exposure) {
  const double scale = std::exp2(exposure);
  LinearPlanes out(linear.width, linear.height);
  for (size_t p = 0; p < linear.pixels(); ++p) {
    for (size_t c = 0; c < 3; ++c) {
      out.c[c].v[p] = float(std::clamp(flip_aces_tonemap(scale * linear.rgb[3 * p + c]), 0.0, 1.0));
    }
  }
  return out;
}

// The x ≥ 0 the tone mapper maps to t: the larger root of (c₀ − t c₃)x² + (c₁ − t c₄)x + (c₂ − t c₅) = 0.
double tonemap_inverse(double t) {
  const double a = kAces[0] - t * kAces[3], b = kAces[1] - t * kAces[4], c = kAces[2] - t * kAces[5];
  if (a == 0) return -c / b;
  const double mid = -0.5 * b / a;
  return mid + std::sqrt(mid * mid - c / a);
}

}  // namespace

double flip_aces_tonemap(double x) {
  return (kAces[0] * x * x + kAces[1] * x + kAces[2]) / (kAces[3] * x * x + kAces[4] * x + kAces[5]);
}

std::vector<float> flip_ldr_map(const RgbImage& test_srgb, const RgbImage& reference_srgb, double pixels_per_degree) {
  check_inputs(test_srgb, reference_srgb, pixels_per_degree);
  if (test_srgb.pixels() == 0) return {};
  const FiniteInputs in = finite_inputs(test_srgb, reference_srgb);
  std::vector<float> map =
      flip_of_linear(linear_from_srgb_image(in.test), linear_from_srgb_image(in.reference), filters_for(pixels_per_degree));
  mark_bad(map, in.bad);
  return map;
}

FlipExposures flip_hdr_exposures(const RgbImage& linear) {
  std::vector<double> luminance;
  luminance.reserve(linear.pixels());
  for (size_t p = 0; p < linear.pixels(); ++p) {
    if (!finite_pixel(linear, p)) continue;
    // Rec. 709 luminance, as HDR-FLIP measures its reference.
    luminance.push_back(0.2126 * linear.rgb[3 * p] + 0.7152 * linear.rgb[3 * p + 1] + 0.0722 * linear.rgb[3 * p + 2]);
  }
  if (luminance.empty()) return {};
  const double y_max = *std::max_element(luminance.begin(), luminance.end());
  if (!(y_max > 0)) return {};
  auto middle = luminance.begin() + std::ptrdiff_t(luminance.size() / 2);
  std::nth_element(luminance.begin(), middle, luminance.end());
  double y_median = *middle;
  if (!(y_median > 0)) {
    std::vector<double> positive;
    for (double y : luminance) {
      if (y > 0) positive.push_back(y);
    }
    middle = positive.begin() + std::ptrdiff_t(positive.size() / 2);
    std::nth_element(positive.begin(), middle, positive.end());
    y_median = *middle;
  }
  const double x_target = tonemap_inverse(kExposureTarget);
  FlipExposures e;
  e.start = std::log2(x_target / y_max);  // the brightest pixel at 0.85
  e.stop = std::log2(x_target / y_median);  // the median pixel at 0.85
  e.count = int(std::max(2.0, std::ceil(e.stop - e.start)));
  e.found = true;
  return e;
}

std::vector<float> flip_hdr_map(const RgbImage& test, const RgbImage& reference, double pixels_per_degree) {
  check_inputs(test, reference, pixels_per_degree);
  if (test.pixels() == 0) return {};
  const FiniteInputs in = finite_inputs(test, reference);
  FlipExposures exposures = flip_hdr_exposures(in.reference);
  if (!exposures.found) exposures = flip_hdr_exposures(in.test);
  const Filters f = filters_for(pixels_per_degree);
  const int count = exposures.start == exposures.stop ? 1 : exposures.count;  // one exposure repeated gives the same map
  std::vector<float> map(test.pixels(), 0.0f);
  for (int i = 0; i < count; ++i) {
    const double exposure =
        count == 1 ? exposures.start : exposures.start + i * (exposures.stop - exposures.start) / (count - 1);
    const std::vector<float> ldr = flip_of_linear(tone_mapped(in.test, exposure), tone_mapped(in.reference, exposure), f);
    for (size_t p = 0; p < map.size(); ++p) map[p] = std::max(map[p], ldr[p]);  // the largest over the exposures
  }
  mark_bad(map, in.bad);
  return map;
}

}  // namespace volgraph::compare
