// Frame images on disk. DESIGN.md: row 0 is the top of every image; .png is
// tone-mapped sRGB 8-bit, .exr and .pfm linear float. An image is encoded in memory
// first, then written with every write, flush and close checked (output_files.h stages
// several outputs and renames them into place together), so a failure leaves no file.
#pragma once

#include <cstddef>
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

// The bytes of `image` as a file of `format`.
std::vector<std::byte> encode_image(const Image& image, ImageFormat format);

// The bytes of a PNG of 8-bit RGBA texels as they are (no transfer function applied):
// 4 bytes a pixel, row 0 at the top. For pictures already made for display (tone-mapped
// images, heatmaps). Throws std::invalid_argument when the size does not match.
std::vector<std::byte> encode_png_rgba8(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba);

// Writes one image: ConfigError (the path is the user's input, named with `flag`, e.g.
// "-o") for an unsupported type or a target that cannot take a file; IoError
// (output_files.h) when the write itself fails. Nothing is left behind on failure.
void write_image(const std::string& path, const Image& image, const std::string& flag = "-o");

// Reads a .pfm written by write_image (or any colour PFM). Throws ConfigError.
Image read_pfm(const std::string& path);

}  // namespace volgraph
