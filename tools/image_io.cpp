#include "tools/image_io.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <stdexcept>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include "graph/diagnostics.h"
#include "physics/srgb.h"
#include "tools/output_files.h"

namespace volgraph {
namespace {

[[noreturn]] void fail(const std::string& flag, const std::string& path, const std::string& message) {
  throw ConfigError({{{"<command line>", flag + " " + path, 0}, message}});
}

void append(std::vector<std::byte>& out, const void* data, size_t size) {
  const auto* bytes = static_cast<const std::byte*>(data);
  out.insert(out.end(), bytes, bytes + size);
}

std::vector<std::byte> encode_png(const Image& image) {
  std::vector<uint8_t> texels(size_t(image.width) * image.height * 4);
  for (size_t i = 0; i < texels.size(); ++i) {
    const float v = (i % 4 == 3) ? std::clamp(image.rgba[i], 0.0f, 1.0f) : physics::srgb_encode(image.rgba[i]);
    texels[i] = uint8_t(std::lround(v * 255.0f));
  }
  return encode_png_rgba8(image.width, image.height, texels);
}

std::vector<std::byte> encode_exr(const Image& image) {
  Imf::Header header(int(image.width), int(image.height));
  Imf::FrameBuffer frame;
  const char* names[] = {"R", "G", "B", "A"};
  char* base = reinterpret_cast<char*>(const_cast<float*>(image.rgba.data()));
  for (int c = 0; c < 4; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + 4 * c, 16, size_t(image.width) * 16));
  }
  Imf::StdOSStream stream;
  {
    Imf::OutputFile out(stream, header);
    out.setFrameBuffer(frame);
    out.writePixels(int(image.height));
  }  // the file is complete once closed
  const std::string bytes = stream.str();
  std::vector<std::byte> result;
  append(result, bytes.data(), bytes.size());
  return result;
}

// PFM stores scanlines bottom to top: the last one written is row 0, the top.
std::vector<std::byte> encode_pfm(const Image& image) {
  const std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  std::vector<std::byte> out;
  out.reserve(header.size() + size_t(image.width) * image.height * 12);
  append(out, header.data(), header.size());
  std::vector<float> row(size_t(image.width) * 3);
  for (uint32_t y = image.height; y-- > 0;) {
    for (uint32_t x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) row[3 * x + c] = image.rgba[4 * (size_t(y) * image.width + x) + c];
    }
    append(out, row.data(), row.size() * sizeof(float));
  }
  return out;
}

}  // namespace

std::vector<std::byte> encode_png_rgba8(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba) {
  if (rgba.size() != size_t(width) * height * 4) throw std::invalid_argument("encode_png_rgba8: the texels do not match the size");
  std::vector<std::byte> out;
  auto collect = [](void* context, void* data, int size) { append(*static_cast<std::vector<std::byte>*>(context), data, size_t(size)); };
  if (!stbi_write_png_to_func(collect, &out, int(width), int(height), 4, rgba.data(), int(width * 4))) {
    throw std::runtime_error("the PNG encoder failed");
  }
  return out;
}

std::optional<ImageFormat> image_format_for(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
  if (ext == ".png") return ImageFormat::png;
  if (ext == ".exr") return ImageFormat::exr;
  if (ext == ".pfm") return ImageFormat::pfm;
  return std::nullopt;
}

std::vector<std::byte> encode_image(const Image& image, ImageFormat format) {
  switch (format) {
    case ImageFormat::png: return encode_png(image);
    case ImageFormat::exr: return encode_exr(image);
    case ImageFormat::pfm: return encode_pfm(image);
  }
  return {};
}

void write_image(const std::string& path, const Image& image, const std::string& flag) {
  const auto format = image_format_for(path);
  if (!format) fail(flag, path, "unsupported image type; expected a .png, .exr or .pfm file name");
  check_output_target(path, flag);
  OutputFiles files;
  files.stage(path, flag, encode_image(image, *format));
  files.commit();
}

Image read_pfm(const std::string& path) {
  // Only a regular file: opening a FIFO or a device would block or never end.
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) fail("pfm", path, "no such file");
  if (!std::filesystem::is_regular_file(status)) fail("pfm", path, "is not a regular file (a folder, FIFO or device); expected a .pfm file");
  const uintmax_t file_bytes = std::filesystem::file_size(path, ec);
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f || ec) {
    if (f) std::fclose(f);
    fail("pfm", path, "cannot open it");
  }
  char kind[3] = {};
  unsigned w = 0, h = 0;
  float scale = 0;
  const bool header = std::fscanf(f, "%2s %u %u %f", kind, &w, &h, &scale) == 4 && std::fgetc(f) != EOF;
  Image image;
  if (!header || std::string(kind) != "PF" || scale >= 0 || w == 0 || h == 0 || w > 65536 || h > 65536) {
    std::fclose(f);
    fail("pfm", path, "not a little-endian colour PFM");
  }
  // The header's size against the file's before any allocation: a header may claim 65536².
  const uintmax_t pixel_bytes = uintmax_t(w) * h * 3 * sizeof(float);
  const long header_bytes = std::ftell(f);
  if (header_bytes < 0 || file_bytes < uintmax_t(header_bytes) + pixel_bytes) {
    std::fclose(f);
    fail("pfm", path, "truncated: its header says " + std::to_string(w) + "x" + std::to_string(h) + " (" +
                          std::to_string(uintmax_t(header_bytes) + pixel_bytes) + " bytes), the file holds " + std::to_string(file_bytes));
  }
  image.width = w;
  image.height = h;
  image.rgba.assign(size_t(w) * h * 4, 1.0f);
  std::vector<float> row(size_t(w) * 3);
  for (uint32_t y = h; y-- > 0;) {
    if (std::fread(row.data(), sizeof(float), row.size(), f) != row.size()) {
      std::fclose(f);
      fail("pfm", path, "truncated");
    }
    for (uint32_t x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) image.rgba[4 * (size_t(y) * w + x) + c] = row[3 * x + c];
    }
  }
  std::fclose(f);
  return image;
}

}  // namespace volgraph
