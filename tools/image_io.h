// Frame images on disk. DESIGN.md: row 0 is the top of every image; .png is
// tone-mapped sRGB 8-bit, .exr and .pfm linear float. Writes go to a temporary name
// in the same folder and are renamed into place, so a failure leaves no partial file.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace volgraph {

struct Image {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;  // 4 floats a pixel, row 0 at the top
};

enum class ImageFormat { png, exr, pfm };

std::optional<ImageFormat> image_format_for(const std::string& path);

// Throws ConfigError (the output path is the user's input) naming `flag` (e.g. "-o").
void write_image(const std::string& path, const Image& image, const std::string& flag = "-o");

// Reads a .pfm written by write_image (or any colour PFM). Throws ConfigError.
Image read_pfm(const std::string& path);

}  // namespace volgraph
