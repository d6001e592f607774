// How a pass touches a resource, and the synchronisation state each use needs.
// Stages, accesses and layouts mirror Vulkan synchronization2 so the Vulkan backend
// maps them one to one; the WebGPU backend turns usages into usage flags.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "graph/resource.h"
#include "graph/rhi/types.h"

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

AccessState access_state(Usage usage, PassKind pass_kind, ResourceKind resource_kind);

}  // namespace volgraph
