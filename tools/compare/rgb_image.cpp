#include "tools/compare/rgb_image.h"

namespace volgraph::compare {

RgbImage rgb_from_rgba(uint32_t width, uint32_t height, const std::vector<float>& rgba) {
  RgbImage out{width, height, std::vector<float>(size_t(width) * height * 3)};
  for (size_t p = 0; p < out.pixels(); ++p) {
    for (size_t c = 0; c < 3; ++c) out.rgb[3 * p + c] = rgba[4 * p + c];
  }
  return out;
}

std::vector<float> rgba_from_rgb(const RgbImage& image) {
  std::vector<float> out(image.pixels() * 4, 1.0f);
  for (size_t p = 0; p < image.pixels(); ++p) {
    for (size_t c = 0; c < 3; ++c) out[4 * p + c] = image.rgb[3 * p + c];
  }
  return out;
}

}  // namespace volgraph::compare
