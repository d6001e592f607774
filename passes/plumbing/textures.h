// Colour textures of materials: 8-bit RGBA images stored sRGB-encoded (glTF's base
// colour and emission, a material's albedo_texture), their mip chains filtered in linear
// light, and a per-device cache so an image used by many objects is uploaded once.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "graph/rhi/rhi.h"

namespace volgraph::plumbing {

struct Rgba8Image {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> texels;  // row 0 at the top, 4 bytes a texel
  uint32_t channels = 4;        // the file's own channels (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA)
};

// Decodes PNG, JPEG, BMP, TGA… (stb_image) to RGBA; throws ConfigError (the image is
// the user's input) saying why it cannot be decoded, named by `describe`.
Rgba8Image decode_image(const uint8_t* bytes, size_t size, const std::string& describe);
Rgba8Image read_image_file(const std::string& path);
// Whether the bytes are an image decode_image reads, without decoding it ("" if so,
// else why not): stb_image's header check, and for a PNG every chunk whole with its CRC.
std::string image_problem(const uint8_t* bytes, size_t size);
std::string image_file_problem(const std::string& path);

// Levels 0…n−1 down to 1×1, each texel the mean of the 2×2 (or 1×2, 2×1) texels above it
// in linear light (a box filter; colour decoded from sRGB, alpha linear).
std::vector<Rgba8Image> srgb_mip_chain(Rgba8Image level0);
// The same for data stored linear: the box mean of the stored values.
std::vector<Rgba8Image> linear_mip_chain(Rgba8Image level0);

struct SamplerWrap {
  rhi::AddressMode u = rhi::AddressMode::repeat, v = rhi::AddressMode::repeat;
  friend bool operator<(const SamplerWrap& a, const SamplerWrap& b) { return std::tie(a.u, a.v) < std::tie(b.u, b.v); }
};

class TextureCache {
 public:
  explicit TextureCache(rhi::Device& device) : device_(device) {}
  // The view of an sRGB texture with its mip chain, loaded by `load` on the device's first
  // use of `key` (rhi::Device::cached_texture_view: shared by every pass on the device).
  rhi::TextureViewId srgb(const std::string& key, const std::function<Rgba8Image()>& load);
  // The same for data stored linear (glTF's transmission and thickness textures): rgba8 unorm,
  // its mip chain filtered on the stored values.
  rhi::TextureViewId linear(const std::string& key, const std::function<Rgba8Image()>& load);
  // 1×1 white: the texture of a material without one (factor × 1).
  rhi::TextureViewId white();
  // Trilinear, with the wrap modes given.
  rhi::SamplerId sampler(SamplerWrap wrap);

 private:
  rhi::TextureViewId upload(const std::string& label, const std::vector<Rgba8Image>& chain, Format format);

  rhi::Device& device_;
  std::map<SamplerWrap, rhi::SamplerId> samplers_;
};

}  // namespace volgraph::plumbing
