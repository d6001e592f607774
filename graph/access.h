// How a pass touches a resource, and the synchronisation state each use needs.
// Stages, accesses and layouts mirror Vulkan synchronization2 so the Vulkan backend
// maps them one to one; the WebGPU backend turns usages into usage flags.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "graph/resource.h"

namespace volgraph {

enum class PassKind : uint8_t { compute, graphics, transfer };

// What a slot does with its resource (one per slot).
enum class Usage : uint8_t {
  sampled,             // texture read through a sampler
  storage_read,        // storage texture or buffer, read
  storage_write,       // storage texture or buffer, written (contents discarded first)
  storage_read_write,  // storage, read and written
  uniform_read,        // uniform buffer
  color_attachment,    // render target, cleared or overwritten
  color_attachment_load,  // render target, loaded then written (blending onto it)
  depth_attachment,    // depth test and write
  depth_read,          // depth test only, read-only layout
  copy_src,
  copy_dst,
};

std::string_view usage_name(Usage usage);
bool usage_from_name(std::string_view name, Usage* out);
bool usage_reads(Usage usage);
bool usage_writes(Usage usage);
// Whether `usage` suits a resource of `kind` (attachments are 2D textures, etc.).
bool usage_fits_kind(Usage usage, ResourceKind kind);

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

AccessState access_state(Usage usage, PassKind pass_kind, ResourceKind resource_kind);

}  // namespace volgraph
