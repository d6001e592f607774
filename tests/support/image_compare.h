// How far a rendered image is from a reference, in the metrics the golden-image tests
// state: the mean absolute error relative to the reference's mean, and the fraction of
// pixels off by more than a relative threshold (outliers: a moved edge, a broken texel).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace volgraph::testing {

// Two steps of a half float's rounding at `value` (10-bit mantissa; normals down to 6.1e-5):
// the tolerance of a value read back from an rgba16_float target.
inline double fp16_steps(double value) { return 2 * std::ldexp(1.0, std::ilogb(std::max(std::abs(value), 6.1e-5)) - 10); }

// Whether every float of a read-back image (anything with `rgba`: Texels) is finite: no NaN
// or infinity left a pass.
template <typename Image>
bool all_finite(const Image& image) {
  return std::all_of(image.rgba.begin(), image.rgba.end(), [](float v) { return std::isfinite(v); });
}

struct ImageDifference {
  double relative_mean_error = 0;  // Σ|a − b| / Σ|b| over RGB
  double outlier_fraction = 0;     // pixels with a channel off by > outlier_threshold · max(|b|, mean |b|)
  double max_abs_error = 0;
  size_t non_finite = 0;           // NaN or Inf values in a
  std::string describe() const;
};

// a and b: RGBA float images of one size (alpha ignored).
ImageDifference compare_images(const std::vector<float>& a, const std::vector<float>& b, double outlier_threshold = 0.05);

}  // namespace volgraph::testing
