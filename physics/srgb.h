// The sRGB transfer function (IEC 61966-2-1): 8-bit images and textures are stored
// encoded, shading is done in linear light.
#pragma once

#include <algorithm>
#include <cmath>

namespace volgraph::physics {

// Linear [0, 1] → encoded [0, 1]; clamps outside.
inline float srgb_encode(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Encoded [0, 1] → linear [0, 1]; clamps outside.
inline float srgb_decode(float encoded) {
  const float c = std::clamp(encoded, 0.0f, 1.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace volgraph::physics
