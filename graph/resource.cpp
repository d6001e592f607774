#include <algorithm>
#include "graph/resource.h"

#include <array>

namespace volgraph {
namespace {

constexpr std::array<FormatInfo, 14> kFormats = {{
    {"undefined", 0, false, false},
    {"r8_unorm", 1, false, false},
    {"rgba8_unorm", 4, false, true},
    {"rgba8_srgb", 4, false, false},
    {"r16_float", 2, false, false},
    {"rg16_float", 4, false, false},
    {"rgba16_float", 8, false, true},
    {"r32_float", 4, false, true},
    {"rg32_float", 8, false, true},
    {"rgba32_float", 16, false, true},
    {"r11g11b10_float", 4, false, false},
    {"r32_uint", 4, false, true},
    {"d16_unorm", 2, true, false},
    {"d32_float", 4, true, false},
}};

constexpr std::array<std::string_view, 4> kKinds = {"texture2d", "texture3d", "buffer", "texture_cube"};

}  // namespace

const FormatInfo& format_info(Format format) { return kFormats[static_cast<size_t>(format)]; }

std::optional<Format> format_from_name(std::string_view name) {
  for (size_t i = 1; i < kFormats.size(); ++i) {
    if (kFormats[i].name == name) return static_cast<Format>(i);
  }
  return std::nullopt;
}

std::string_view kind_name(ResourceKind kind) { return kKinds[static_cast<size_t>(kind)]; }

std::optional<ResourceKind> kind_from_name(std::string_view name) {
  for (size_t i = 0; i < kKinds.size(); ++i) {
    if (kKinds[i] == name) return static_cast<ResourceKind>(i);
  }
  return std::nullopt;
}

SizeSpec SizeSpec::fixed(uint32_t w, uint32_t h, uint32_t d) {
  SizeSpec s;
  s.mode = Mode::absolute;
  s.absolute = {w, h, d};
  return s;
}

SizeSpec SizeSpec::of_output(float sx, float sy, uint32_t depth) {
  SizeSpec s;
  s.mode = Mode::relative;
  s.scale_x = sx;
  s.scale_y = sy;
  s.absolute.depth = depth;
  return s;
}

SizeSpec SizeSpec::of_output_divided(ParamHandle<int64_t> divisor, ParamHandle<int64_t> slices) {
  SizeSpec s = of_output(1.0f, 1.0f, 1);
  s.divisor_param = divisor.index;
  s.param = slices.index;
  return s;
}

SizeSpec SizeSpec::square_of(ParamHandle<int64_t> side) {
  SizeSpec s;
  s.mode = Mode::square_param;
  s.param = side.index;
  return s;
}

SizeSpec SizeSpec::square_layers_of(ParamHandle<int64_t> side, ParamHandle<int64_t> depth) {
  SizeSpec s = square_of(side);
  s.depth_param = depth.index;
  return s;
}

SizeSpec SizeSpec::with_mips(ParamHandle<int64_t> levels) const {
  SizeSpec s = *this;
  s.mip_param = levels.index;
  return s;
}

SizeSpec SizeSpec::row_of(ParamHandle<int64_t> width) {
  SizeSpec s = square_of(width);
  s.fixed_height = 1;
  return s;
}

SizeSpec SizeSpec::rect_of(ParamHandle<int64_t> width, ParamHandle<int64_t> height) {
  SizeSpec s = square_of(width);
  s.height_param = height.index;
  return s;
}

SizeSpec SizeSpec::volume_of(ParamHandle<int64_t> width, ParamHandle<int64_t> height, ParamHandle<int64_t> depth) {
  SizeSpec s = rect_of(width, height);
  s.depth_param = depth.index;
  return s;
}

SizeSpec SizeSpec::bytes(uint64_t n) {
  SizeSpec s;
  s.mode = Mode::absolute;
  s.buffer_bytes = n;
  return s;
}

std::vector<uint16_t> SizeSpec::params() const {
  std::vector<uint16_t> out;
  for (const ParamIndex& p : {param, divisor_param, depth_param, height_param, mip_param}) {
    if (p) out.push_back(*p);
  }
  return out;
}

uint32_t full_mip_chain(Extent extent) {
  uint32_t largest = std::max({extent.width, extent.height, extent.depth}), levels = 1;
  while (largest > 1) largest >>= 1, ++levels;
  return levels;
}

uint64_t content_bytes(const ResourceDesc& desc) {
  if (desc.kind == ResourceKind::buffer) return desc.buffer_bytes;
  uint64_t texels = 0;
  for (uint32_t level = 0; level < std::max(1u, desc.mip_levels); ++level) {
    texels += uint64_t{std::max(1u, desc.extent.width >> level)} * std::max(1u, desc.extent.height >> level) *
              std::max(1u, desc.extent.depth >> level);
  }
  return uint64_t{format_info(desc.format).bytes_per_texel} * texels * array_layers(desc.kind);
}

}  // namespace volgraph
