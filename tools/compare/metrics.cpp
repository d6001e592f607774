// The error figures of metrics.h over a mask: sums over the compared pixels, SSIM
// (ssim.h) of the luminance and the HDR-FLIP map (flip.h) averaged over them.
#include "tools/compare/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tools/compare/flip.h"
#include "tools/compare/ssim.h"

namespace volgraph::compare {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string size_text(const RgbImage& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

void check_sizes(const RgbImage& test, const RgbImage& reference) {
  if (test.width != reference.width || test.height != reference.height) {
    throw std::invalid_argument("image metrics: the test image is " + size_text(test) + ", the reference " +
                                size_text(reference));
  }
  if (test.rgb.size() != 3 * test.pixels() || reference.rgb.size() != 3 * reference.pixels()) {
    throw std::invalid_argument("image metrics: an image does not hold 3 floats a pixel");
  }
}

void check_mask(const PixelMask& mask, const RgbImage& image) {
  if (!mask.empty() && mask.size() != image.pixels()) {
    throw std::invalid_argument("image metrics: the mask has " + std::to_string(mask.size()) + " pixels, the images " +
                                std::to_string(image.pixels()));
  }
}

bool finite_pixel(const RgbImage& image, size_t p) {
  return std::isfinite(image.rgb[3 * p]) && std::isfinite(image.rgb[3 * p + 1]) && std::isfinite(image.rgb[3 * p + 2]);
}

// Rec. 709 (ITU-R BT.709) luminance of linear RGB.
double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

// A ratio whose denominator may be 0: 0/0 is 0, x/0 is +inf.
double ratio(double numerator, double denominator) {
  if (denominator > 0) return numerator / denominator;
  return numerator > 0 ? kInfinity : 0.0;
}

// Sums over the compared pixels' channels.
struct ChannelSums {
  double squared_error = 0, squared_reference = 0, abs_error = 0, abs_reference = 0;
  double max_abs_error = 0, peak = -kInfinity;
  size_t values = 0;
};

// Mean SSIM over the compared pixels: luminance planes in which a left-out pixel's test
// value is the reference's (both 0 where the reference is not finite).
double mean_ssim(const RgbImage& test, const RgbImage& reference, const std::vector<bool>& compared,
                 size_t compared_pixels, double dynamic_range) {
  std::vector<double> t(test.pixels()), r(test.pixels());
  for (size_t p = 0; p < test.pixels(); ++p) {
    const bool reference_finite = finite_pixel(reference, p);
    r[p] = reference_finite ? luminance(&reference.rgb[3 * p]) : 0.0;
    t[p] = finite_pixel(test, p) && reference_finite ? luminance(&test.rgb[3 * p]) : r[p];
  }
  const std::vector<double> map = ssim_map(t, r, test.width, test.height, dynamic_range);
  double sum = 0;
  for (size_t p = 0; p < map.size(); ++p) {
    if (compared[p]) sum += map[p];
  }
  return sum / double(compared_pixels);
}

double mean_over(const std::vector<float>& map, const std::vector<bool>& compared, size_t compared_pixels) {
  double sum = 0;
  for (size_t p = 0; p < map.size(); ++p) {
    if (compared[p]) sum += map[p];
  }
  return sum / double(compared_pixels);
}

// Nothing compared (an empty mask, no pixel finite in both images) is no match at all:
// every figure NaN, never the 0 error, infinite PSNR and SSIM 1 of a perfect one.
ErrorMetrics nothing_compared(ErrorMetrics m) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  m.rmse = m.relative_rmse = m.psnr_db = m.ssim = m.flip = m.max_abs_error = m.relative_mean_error = none;
  return m;
}

// Every figure but FLIP; `compared` returns which pixels entered them.
ErrorMetrics measure_without_flip(const RgbImage& test, const RgbImage& reference, const PixelMask& mask,
                                  std::vector<bool>& compared) {
  ErrorMetrics m;
  ChannelSums s;
  compared.assign(test.pixels(), false);
  for (size_t p = 0; p < test.pixels(); ++p) {
    if (!mask.empty() && !mask[p]) continue;
    for (size_t c = 0; c < 3; ++c) {
      const float v = test.rgb[3 * p + c];
      if (std::isnan(v)) ++m.nan_values;
      if (std::isinf(v)) ++m.inf_values;
    }
    if (!finite_pixel(test, p) || !finite_pixel(reference, p)) continue;
    compared[p] = true;
    ++m.compared_pixels;
    for (size_t c = 0; c < 3; ++c) {
      const double t = test.rgb[3 * p + c], r = reference.rgb[3 * p + c], e = std::fabs(t - r);
      s.squared_error += e * e;
      s.squared_reference += r * r;
      s.abs_error += e;
      s.abs_reference += std::fabs(r);
      s.max_abs_error = std::max(s.max_abs_error, e);
      s.peak = std::max(s.peak, r);
      ++s.values;
    }
  }
  if (m.compared_pixels == 0) return nothing_compared(m);
  m.rmse = std::sqrt(s.squared_error / double(s.values));
  m.relative_rmse = ratio(m.rmse, std::sqrt(s.squared_reference / double(s.values)));
  m.max_abs_error = s.max_abs_error;
  m.relative_mean_error = ratio(s.abs_error, s.abs_reference);
  const double dynamic_range = s.peak > 0 ? s.peak : 1.0;  // a black reference: the range of a display, 1
  m.psnr_db = m.rmse > 0 ? 20.0 * std::log10(dynamic_range / m.rmse) : kInfinity;  // PSNR = 20 log10(peak / RMSE)
  m.ssim = mean_ssim(test, reference, compared, m.compared_pixels, dynamic_range);
  return m;
}

}  // namespace

ErrorMetrics measure_error_with_flip_map(const RgbImage& test, const RgbImage& reference, const PixelMask& mask,
                                         const std::vector<float>& flip_map) {
  check_sizes(test, reference);
  check_mask(mask, test);
  if (flip_map.size() != test.pixels()) {
    throw std::invalid_argument("image metrics: the FLIP map has " + std::to_string(flip_map.size()) +
                                " values, the images " + std::to_string(test.pixels()) + " pixels");
  }
  std::vector<bool> compared;
  ErrorMetrics m = measure_without_flip(test, reference, mask, compared);
  if (m.compared_pixels > 0) m.flip = mean_over(flip_map, compared, m.compared_pixels);
  return m;
}

ErrorMetrics measure_error(const RgbImage& test, const RgbImage& reference, const PixelMask& mask,
                           double pixels_per_degree) {
  check_sizes(test, reference);
  check_mask(mask, test);
  return measure_error_with_flip_map(test, reference, mask, flip_hdr_map(test, reference, pixels_per_degree));
}

std::vector<float> abs_error_map(const RgbImage& test, const RgbImage& reference) {
  check_sizes(test, reference);
  std::vector<float> map(test.pixels());
  for (size_t p = 0; p < map.size(); ++p) {
    if (!finite_pixel(test, p) || !finite_pixel(reference, p)) {
      map[p] = std::numeric_limits<float>::infinity();
      continue;
    }
    float largest = 0;
    for (size_t c = 0; c < 3; ++c) largest = std::max(largest, std::fabs(test.rgb[3 * p + c] - reference.rgb[3 * p + c]));
    map[p] = largest;
  }
  return map;
}

const std::vector<std::string>& metric_names() {
  static const std::vector<std::string> names{"rmse", "rel_rmse", "psnr", "ssim", "flip", "max_abs", "rel_mean"};
  return names;
}

bool is_metric_name(const std::string& name) {
  const std::vector<std::string>& names = metric_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

namespace {

[[noreturn]] void unknown_metric(const std::string& name) {
  std::string known;
  for (const std::string& n : metric_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown metric \"" + name + "\" (expected one of " + known + ")");
}

}  // namespace

double metric_value(const ErrorMetrics& metrics, const std::string& name) {
  if (name == "rmse") return metrics.rmse;
  if (name == "rel_rmse") return metrics.relative_rmse;
  if (name == "psnr") return metrics.psnr_db;
  if (name == "ssim") return metrics.ssim;
  if (name == "flip") return metrics.flip;
  if (name == "max_abs") return metrics.max_abs_error;
  if (name == "rel_mean") return metrics.relative_mean_error;
  unknown_metric(name);
}

bool metric_lower_is_better(const std::string& name) {
  if (!is_metric_name(name)) unknown_metric(name);
  return name != "psnr" && name != "ssim";
}

}  // namespace volgraph::compare
