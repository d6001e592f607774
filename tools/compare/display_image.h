// A linear image made fit to look at: scaled by an exposure, clamped to [0, 1] and
// sRGB-encoded to 8 bits (IEC 61966-2-1). One report shows every image at the same
// exposure, found from one key image (the reference when there is one), so that equal
// radiance looks equal across the images.
#pragma once

#include <cstdint>
#include <vector>

#include "tools/compare/rgb_image.h"

namespace volgraph::compare {

// 8-bit RGBA texels as they are shown: 4 bytes a pixel, row 0 at the top.
struct Rgba8Image {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba;
};

// The luminance (Rec. ITU-R BT.709 weights) that maps to this display value.
constexpr double kDisplayKeyValue = 0.9;
constexpr double kDisplayKeyPercentile = 0.99;

// The exposure that maps the 99th percentile luminance of the finite pixels of `key`
// to kDisplayKeyValue; the largest luminance when that percentile is 0; 1 for a black
// or empty image.
double display_exposure(const RgbImage& key);

// `image` × exposure, clamped and sRGB-encoded, alpha 255. Pixels with a non-finite
// channel are shown in kNonFiniteColour.
Rgba8Image display_image(const RgbImage& image, double exposure);

// Marks the pixels of a shown image that have a NaN or ±Inf channel.
constexpr uint8_t kNonFiniteColour[3] = {255, 0, 255};

}  // namespace volgraph::compare
