// Small images with known content for the metric and FLIP tests.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "tools/compare/rgb_image.h"

namespace volgraph::compare::test_images {

inline RgbImage constant(uint32_t width, uint32_t height, std::array<float, 3> rgb) {
  RgbImage image{width, height, {}};
  image.rgb.resize(image.pixels() * 3);
  for (size_t p = 0; p < image.pixels(); ++p) {
    for (size_t c = 0; c < 3; ++c) image.rgb[3 * p + c] = rgb[c];
  }
  return image;
}

// Squares of `cell` pixels alternating between `dark` and `light` (grey).
inline RgbImage checkerboard(uint32_t width, uint32_t height, uint32_t cell, float dark, float light) {
  RgbImage image = constant(width, height, {0, 0, 0});
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const float v = ((x / cell + y / cell) % 2) ? light : dark;
      for (size_t c = 0; c < 3; ++c) image.rgb[3 * (size_t(y) * width + x) + c] = v;
    }
  }
  return image;
}

// The mean over the (2 radius + 1)² square around each pixel, the edges clamped.
inline RgbImage box_blurred(const RgbImage& in, int radius) {
  RgbImage out = in;
  const int w = int(in.width), h = int(in.height);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (size_t c = 0; c < 3; ++c) {
        double sum = 0;
        for (int dy = -radius; dy <= radius; ++dy) {
          for (int dx = -radius; dx <= radius; ++dx) {
            const int sx = std::clamp(x + dx, 0, w - 1), sy = std::clamp(y + dy, 0, h - 1);
            sum += in.rgb[3 * (size_t(sy) * w + sx) + c];
          }
        }
        out.rgb[3 * (size_t(y) * w + x) + c] = float(sum / double((2 * radius + 1) * (2 * radius + 1)));
      }
    }
  }
  return out;
}

inline double mean(const std::vector<float>& values) {
  double sum = 0;
  for (float v : values) sum += v;
  return sum / double(values.size());
}

}  // namespace volgraph::compare::test_images
