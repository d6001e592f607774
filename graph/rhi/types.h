// The vocabulary the backend interface (rhi.h) and the graph share: resource kinds,
// texel formats, extents, and the synchronisation state of a resource (stages,
// accesses, layouts, mirroring Vulkan synchronization2). Declared here, below both,
// so that rhi.h needs no graph/ header; graph/resource.h and graph/access.h build on it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace volgraph {

// texture_cube: six square faces (+x, −x, +y, −y, +z, −z: Vulkan's and WebGPU's layer
// order), sampled as a cube; its per-level views are the faces as a 2D array (storage
// writes, one face per layer).
enum class ResourceKind : uint8_t { texture2d, texture3d, buffer, texture_cube };

// The array layers a texture of `kind` has (a cube's six faces; else one).
constexpr uint32_t array_layers(ResourceKind kind) { return kind == ResourceKind::texture_cube ? 6u : 1u; }

// Texel formats a slot may hold. Storage-capable ones match WebGPU storage formats.
enum class Format : uint8_t {
  undefined,
  r8_unorm,
  rgba8_unorm,
  rgba8_srgb,
  r16_float,
  rg16_float,
  rgba16_float,
  r32_float,
  rg32_float,
  rgba32_float,
  r11g11b10_float,
  r32_uint,
  d16_unorm,
  d32_float,
};

struct FormatInfo {
  std::string_view name;
  uint32_t bytes_per_texel;
  bool is_depth;
  bool storage_capable;  // usable as a storage texture on both backends
};

const FormatInfo& format_info(Format format);
std::optional<Format> format_from_name(std::string_view name);
std::string_view kind_name(ResourceKind kind);
std::optional<ResourceKind> kind_from_name(std::string_view name);

struct Extent {
  uint32_t width = 1;
  uint32_t height = 1;
  uint32_t depth = 1;
  friend bool operator==(const Extent&, const Extent&) = default;
};

namespace stage {  // pipeline stage bits
constexpr uint32_t none = 0;
constexpr uint32_t vertex_shader = 1u << 0;
constexpr uint32_t fragment_shader = 1u << 1;
constexpr uint32_t early_fragment_tests = 1u << 2;
constexpr uint32_t late_fragment_tests = 1u << 3;
constexpr uint32_t color_attachment_output = 1u << 4;
constexpr uint32_t compute_shader = 1u << 5;
constexpr uint32_t copy = 1u << 6;
constexpr uint32_t all_commands = 1u << 7;
}  // namespace stage

namespace access {  // memory access bits
constexpr uint32_t none = 0;
constexpr uint32_t shader_sampled_read = 1u << 0;
constexpr uint32_t shader_storage_read = 1u << 1;
constexpr uint32_t shader_storage_write = 1u << 2;
constexpr uint32_t uniform_read = 1u << 3;
constexpr uint32_t color_attachment_read = 1u << 4;
constexpr uint32_t color_attachment_write = 1u << 5;
constexpr uint32_t depth_stencil_read = 1u << 6;
constexpr uint32_t depth_stencil_write = 1u << 7;
constexpr uint32_t transfer_read = 1u << 8;
constexpr uint32_t transfer_write = 1u << 9;
constexpr uint32_t memory_read = 1u << 10;
constexpr uint32_t memory_write = 1u << 11;
constexpr uint32_t all_writes =
    shader_storage_write | color_attachment_write | depth_stencil_write | transfer_write | memory_write;
}  // namespace access

enum class Layout : uint8_t {
  undefined,  // contents discarded
  general,
  shader_read_only,
  color_attachment,
  depth_attachment,
  depth_read_only,
  transfer_src,
  transfer_dst,
  none,  // buffers have no layout
};

std::string_view layout_name(Layout layout);
std::string stage_names(uint32_t stages);
std::string access_names(uint32_t accesses);

// The synchronisation state a resource must be in for one use.
struct AccessState {
  uint32_t stages = stage::none;
  uint32_t access = access::none;
  Layout layout = Layout::undefined;
  friend bool operator==(const AccessState&, const AccessState&) = default;
};

}  // namespace volgraph
