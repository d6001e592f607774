// A linear RGB image as the comparison tools hold it: 3 floats a pixel, row 0 at the
// top (DESIGN.md), and per-pixel masks over it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgraph::compare {

struct RgbImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgb;  // 3 floats a pixel, row-major, row 0 at the top

  size_t pixels() const { return size_t(width) * height; }
};

// RGBA floats (Texels, Image) to RGB, alpha dropped.
RgbImage rgb_from_rgba(uint32_t width, uint32_t height, const std::vector<float>& rgba);
std::vector<float> rgba_from_rgb(const RgbImage& image);  // alpha 1

// Per pixel (row-major): whether the pixel is compared. Empty means every pixel.
using PixelMask = std::vector<bool>;

}  // namespace volgraph::compare
