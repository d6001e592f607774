#include "passes/plumbing/textures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include <stb/stb_image.h>
#include <zlib.h>

#include "graph/diagnostics.h"
#include "physics/srgb.h"

namespace volgraph::plumbing {

namespace {

std::vector<uint8_t> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A level in linear light, 4 floats a texel.
struct LinearLevel {
  uint32_t width = 0, height = 0;
  std::vector<float> texels;
};

LinearLevel to_linear(const Rgba8Image& image) {
  std::array<float, 256> decode{};
  for (size_t i = 0; i < 256; ++i) decode[i] = physics::srgb_decode(float(i) / 255.0f);
  LinearLevel level{image.width, image.height, std::vector<float>(image.texels.size())};
  for (size_t i = 0; i < image.texels.size(); ++i) {
    level.texels[i] = i % 4 == 3 ? float(image.texels[i]) / 255.0f : decode[image.texels[i]];
  }
  return level;
}

// Stored values as they are (data, not colour), 4 floats a texel in [0, 1].
LinearLevel to_unit(const Rgba8Image& image) {
  LinearLevel level{image.width, image.height, std::vector<float>(image.texels.size())};
  for (size_t i = 0; i < image.texels.size(); ++i) level.texels[i] = float(image.texels[i]) / 255.0f;
  return level;
}

Rgba8Image to_unorm8(const LinearLevel& level) {
  Rgba8Image image{level.width, level.height, std::vector<uint8_t>(level.texels.size())};
  for (size_t i = 0; i < level.texels.size(); ++i) image.texels[i] = uint8_t(std::lround(std::clamp(level.texels[i], 0.0f, 1.0f) * 255.0f));
  return image;
}

Rgba8Image to_srgb8(const LinearLevel& level) {
  Rgba8Image image{level.width, level.height, std::vector<uint8_t>(level.texels.size())};
  for (size_t i = 0; i < level.texels.size(); ++i) {
    const float encoded = i % 4 == 3 ? std::clamp(level.texels[i], 0.0f, 1.0f) : physics::srgb_encode(level.texels[i]);
    image.texels[i] = uint8_t(std::lround(encoded * 255.0f));
  }
  return image;
}

// The next level: each texel the mean of the (up to) 2×2 texels it covers.
LinearLevel half(const LinearLevel& above) {
  LinearLevel level{std::max(1u, above.width / 2), std::max(1u, above.height / 2), {}};
  level.texels.resize(size_t(level.width) * level.height * 4);
  const uint32_t sx = above.width > 1 ? 2 : 1, sy = above.height > 1 ? 2 : 1;
  for (uint32_t y = 0; y < level.height; ++y) {
    for (uint32_t x = 0; x < level.width; ++x) {
      float* out = &level.texels[(size_t(y) * level.width + x) * 4];
      for (uint32_t dy = 0; dy < sy; ++dy) {
        for (uint32_t dx = 0; dx < sx; ++dx) {
          const float* in = &above.texels[(size_t(y * sy + dy) * above.width + x * sx + dx) * 4];
          for (int c = 0; c < 4; ++c) out[c] += in[c];
        }
      }
      for (int c = 0; c < 4; ++c) out[c] /= float(sx * sy);
    }
  }
  return level;
}

}  // namespace

Rgba8Image decode_image(const uint8_t* bytes, size_t size, const std::string& describe) {
  int width = 0, height = 0, components = 0;
  stbi_uc* pixels = stbi_load_from_memory(bytes, int(size), &width, &height, &components, 4);
  if (!pixels) {  // the user's file: bad input, named
    throw ConfigError({{{describe, "", 0}, std::string("not an image volgraph reads (") + stbi_failure_reason() + ")"}});
  }
  Rgba8Image image{uint32_t(width), uint32_t(height), std::vector<uint8_t>(pixels, pixels + size_t(width) * size_t(height) * 4),
                   uint32_t(components)};
  stbi_image_free(pixels);
  return image;
}

Rgba8Image read_image_file(const std::string& path) {
  const std::vector<uint8_t> bytes = read_file(path);
  return decode_image(bytes.data(), bytes.size(), path);
}

namespace {

uint32_t big_endian(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

// A PNG's chunks walked to IEND (ISO/IEC 15948, PNG 2nd ed., §5.3: length, type, data,
// then the CRC-32 of type and data): "" when every chunk is whole and its CRC holds, or
// the bytes are no PNG. What stb_image's header check cannot see: a truncated file or a
// damaged chunk, which fail only when the texels are decoded.
std::string png_chunks_problem(const uint8_t* bytes, size_t size) {
  constexpr uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if (size < 8 || !std::equal(kSignature, kSignature + 8, bytes)) return "";
  for (size_t at = 8;;) {
    if (size - at < 12) return "a truncated PNG: it ends at byte " + std::to_string(size) + " without its IEND chunk";
    const uint32_t length = big_endian(bytes + at);
    if (length > size - at - 12) return "a truncated PNG: the chunk at byte " + std::to_string(at) + " runs past its end";
    const uint8_t* type = bytes + at + 4;
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), type, uInt(length + 4));
    const std::string name(reinterpret_cast<const char*>(type), 4);
    if (crc != big_endian(type + 4 + length)) return "a damaged PNG: chunk " + name + " at byte " + std::to_string(at) + " fails its CRC";
    at += 12 + size_t(length);
    if (name == "IEND") return "";
  }
}

}  // namespace

std::string image_problem(const uint8_t* bytes, size_t size) {
  if (std::string problem = png_chunks_problem(bytes, size); !problem.empty()) return problem;
  int width = 0, height = 0, components = 0;
  if (!stbi_info_from_memory(bytes, int(size), &width, &height, &components)) {
    return std::string("not an image volgraph reads (PNG, JPEG, BMP, TGA): ") + stbi_failure_reason();
  }
  if (width > 16384 || height > 16384) return "larger than 16384 texels on a side";
  return "";
}

std::string image_file_problem(const std::string& path) {
  try {
    const std::vector<uint8_t> bytes = read_file(path);
    return image_problem(bytes.data(), bytes.size());
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::vector<Rgba8Image> srgb_mip_chain(Rgba8Image level0) {
  std::vector<Rgba8Image> chain;
  LinearLevel level = to_linear(level0);
  chain.push_back(std::move(level0));
  while (level.width > 1 || level.height > 1) {
    level = half(level);
    chain.push_back(to_srgb8(level));
  }
  return chain;
}

// The mip chain of data stored linear: each level the box mean of the stored values.
std::vector<Rgba8Image> linear_mip_chain(Rgba8Image level0) {
  std::vector<Rgba8Image> chain;
  LinearLevel level = to_unit(level0);
  chain.push_back(std::move(level0));
  while (level.width > 1 || level.height > 1) {
    level = half(level);
    chain.push_back(to_unorm8(level));
  }
  return chain;
}

rhi::TextureViewId TextureCache::upload(const std::string& label, const std::vector<Rgba8Image>& chain, Format format) {
  rhi::TextureDesc desc;
  desc.label = label;
  desc.format = format;
  desc.size = {chain[0].width, chain[0].height, 1};
  desc.usage = rhi::texture_usage::sampled | rhi::texture_usage::copy_dst;
  desc.mip_levels = uint32_t(chain.size());
  const rhi::TextureId texture = device_.create_texture(desc);
  for (uint32_t level = 0; level < chain.size(); ++level) {
    device_.write_texture(texture, std::as_bytes(std::span(chain[level].texels)), level);
  }
  return device_.create_view(texture);
}

rhi::TextureViewId TextureCache::srgb(const std::string& key, const std::function<Rgba8Image()>& load) {
  return device_.cached_texture_view(key, [&] { return upload(key, srgb_mip_chain(load()), Format::rgba8_srgb); });
}

rhi::TextureViewId TextureCache::linear(const std::string& key, const std::function<Rgba8Image()>& load) {
  return device_.cached_texture_view("linear " + key, [&] { return upload(key, linear_mip_chain(load()), Format::rgba8_unorm); });
}

rhi::TextureViewId TextureCache::white() {
  return srgb("<1x1 white>", [] { return Rgba8Image{1, 1, {255, 255, 255, 255}}; });
}

rhi::SamplerId TextureCache::sampler(SamplerWrap wrap) {
  const auto found = samplers_.find(wrap);
  if (found != samplers_.end()) return found->second;
  rhi::SamplerDesc desc;
  desc.label = "material trilinear";
  desc.filter = desc.mip_filter = rhi::Filter::linear;
  desc.address_u = wrap.u;
  desc.address_v = wrap.v;
  return samplers_[wrap] = device_.create_sampler(desc);
}

}  // namespace volgraph::plumbing
