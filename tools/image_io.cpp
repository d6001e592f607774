#include "tools/image_io.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include "graph/diagnostics.h"
#include "physics/srgb.h"

namespace volgraph {
namespace {

[[noreturn]] void fail(const std::string& flag, const std::string& path, const std::string& message) {
  throw ConfigError({{{"<command line>", flag + " " + path, 0}, message}});
}

bool write_png(const std::string& file, const Image& image) {
  std::vector<uint8_t> bytes(size_t(image.width) * image.height * 4);
  for (size_t i = 0; i < bytes.size(); ++i) {
    const float v = (i % 4 == 3) ? std::clamp(image.rgba[i], 0.0f, 1.0f) : physics::srgb_encode(image.rgba[i]);
    bytes[i] = uint8_t(std::lround(v * 255.0f));
  }
  return stbi_write_png(file.c_str(), int(image.width), int(image.height), 4, bytes.data(), int(image.width * 4)) != 0;
}

bool write_exr(const std::string& file, const Image& image) {
  Imf::Header header(int(image.width), int(image.height));
  Imf::FrameBuffer frame;
  const char* names[] = {"R", "G", "B", "A"};
  char* base = reinterpret_cast<char*>(const_cast<float*>(image.rgba.data()));
  for (int c = 0; c < 4; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + 4 * c, 16, size_t(image.width) * 16));
  }
  Imf::OutputFile out(file.c_str(), header);
  out.setFrameBuffer(frame);
  out.writePixels(int(image.height));
  return true;
}

// PFM stores scanlines bottom to top: the last one written is row 0, the top.
bool write_pfm(const std::string& file, const Image& image) {
  FILE* f = std::fopen(file.c_str(), "wb");
  if (!f) return false;
  bool ok = std::fprintf(f, "PF\n%u %u\n-1.0\n", image.width, image.height) > 0;
  std::vector<float> row(size_t(image.width) * 3);
  for (uint32_t y = image.height; ok && y-- > 0;) {
    for (uint32_t x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) row[3 * x + c] = image.rgba[4 * (size_t(y) * image.width + x) + c];
    }
    ok = std::fwrite(row.data(), sizeof(float), row.size(), f) == row.size();
  }
  return std::fclose(f) == 0 && ok;
}

}  // namespace

std::optional<ImageFormat> image_format_for(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
  if (ext == ".png") return ImageFormat::png;
  if (ext == ".exr") return ImageFormat::exr;
  if (ext == ".pfm") return ImageFormat::pfm;
  return std::nullopt;
}

void write_image(const std::string& path, const Image& image, const std::string& flag) {
  const auto format = image_format_for(path);
  if (!format) fail(flag, path, "unsupported image type; expected a .png, .exr or .pfm file name");
  const std::filesystem::path target(path);
  std::error_code ec;
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  if (!std::filesystem::is_directory(folder, ec)) fail(flag, path, "folder " + folder.string() + " does not exist");
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid()) + target.extension().string();
  bool written = false;
  std::string why = "cannot write it";
  try {
    written = *format == ImageFormat::png ? write_png(temporary, image)
              : *format == ImageFormat::exr ? write_exr(temporary, image)
                                            : write_pfm(temporary, image);
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (written && std::rename(temporary.c_str(), path.c_str()) == 0) return;
  std::filesystem::remove(temporary, ec);
  fail(flag, path, why);
}

Image read_pfm(const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) fail("pfm", path, "cannot open it");
  char kind[3] = {};
  unsigned w = 0, h = 0;
  float scale = 0;
  const bool header = std::fscanf(f, "%2s %u %u %f", kind, &w, &h, &scale) == 4 && std::fgetc(f) != EOF;
  Image image;
  if (!header || std::string(kind) != "PF" || scale >= 0 || w == 0 || h == 0 || w > 65536 || h > 65536) {
    std::fclose(f);
    fail("pfm", path, "not a little-endian colour PFM");
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
