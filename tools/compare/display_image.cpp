#include "tools/compare/display_image.h"

#include <algorithm>
#include <cmath>

#include "physics/srgb.h"

namespace volgraph::compare {
namespace {

// Relative luminance from linear Rec. 709 primaries (ITU-R BT.709-6, item 3.3).
double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

bool finite_pixel(const float* rgb) { return std::isfinite(rgb[0]) && std::isfinite(rgb[1]) && std::isfinite(rgb[2]); }

std::vector<double> finite_luminances(const RgbImage& image) {
  std::vector<double> out;
  out.reserve(image.pixels());
  for (size_t p = 0; p < image.pixels(); ++p) {
    const float* rgb = &image.rgb[3 * p];
    if (finite_pixel(rgb)) out.push_back(std::max(0.0, luminance(rgb)));
  }
  return out;
}

uint8_t to_byte(float encoded) { return uint8_t(std::lround(std::clamp(encoded, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

double display_exposure(const RgbImage& key) {
  std::vector<double> values = finite_luminances(key);
  if (values.empty()) return 1.0;
  const size_t rank = std::min(values.size() - 1, size_t(std::floor(kDisplayKeyPercentile * double(values.size() - 1))));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(rank), values.end());
  double level = values[rank];
  if (level <= 0) level = *std::max_element(values.begin(), values.end());
  return level > 0 ? kDisplayKeyValue / level : 1.0;
}

Rgba8Image display_image(const RgbImage& image, double exposure) {
  Rgba8Image out{image.width, image.height, std::vector<uint8_t>(image.pixels() * 4, 255)};
  for (size_t p = 0; p < image.pixels(); ++p) {
    const float* rgb = &image.rgb[3 * p];
    uint8_t* texel = &out.rgba[4 * p];
    if (!finite_pixel(rgb)) {
      std::copy(kNonFiniteColour, kNonFiniteColour + 3, texel);
      continue;
    }
    for (int c = 0; c < 3; ++c) texel[c] = to_byte(physics::srgb_encode(float(rgb[c] * exposure)));
  }
  return out;
}

}  // namespace volgraph::compare
