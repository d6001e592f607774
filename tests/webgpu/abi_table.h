// abi_table.h — the sizes and field offsets of the webgpu.h structs whose layout volgraph
// relies on, for the x86-64 System V ABI (LP64: pointers, size_t and uint64_t are 8 bytes
// and 8-aligned; enums, WGPUBool and uint32_t 4; doubles 8; WGPUFlags are uint64_t).
// Source of every number: computed by hand from the member order of dawn.json at
// google/dawn df73f162 (2025-06-24), the revision of libwebgpu_wrapper.so — except
// limits::size, also measured from the library (README of shared/webgpu: wgpuAdapterGetLimits
// writes 152 bytes; abi_test.cpp measures it again). Written apart from the headers, so a
// header that reorders, drops or retypes a member disagrees with this table.
#pragma once

#include <cstddef>

namespace volgraph::webgpu_abi {

// {data, length}
namespace string_view {
inline constexpr size_t size = 16, data = 0, length = 8;
}
// {next, sType}
namespace chained_struct {
inline constexpr size_t size = 16, next = 0, sType = 8;
}
namespace future_wait_info {
inline constexpr size_t size = 16, future = 0, completed = 8;
}
// nextInChain, label (16), usage (flags, 8), size, mappedAtCreation (4) + 4 padding
namespace buffer_descriptor {
inline constexpr size_t size = 48, label = 8, usage = 24, bufferSize = 32, mappedAtCreation = 40;
}
// nextInChain, binding (4) + 4 padding, visibility (flags, 8), bindingArraySize (4) + 4,
// buffer (24: next, type, hasDynamicOffset, minBindingSize), sampler (16), texture (24),
// storageTexture (24)
namespace bind_group_layout_entry {
inline constexpr size_t size = 120, binding = 8, visibility = 16, bindingArraySize = 24,
                        buffer = 32, sampler = 56, texture = 72, storageTexture = 96;
}
// nextInChain, 14 × uint32 (8..64), 2 × uint64 (64..80), 3 × uint32 (80..92) + 4,
// maxBufferSize (96), 12 × uint32 (104..152)
namespace limits {
inline constexpr size_t size = 152, maxTextureDimension2D = 12, maxUniformBufferBindingSize = 64,
                        maxStorageBufferBindingSize = 72, maxVertexBuffers = 88, maxBufferSize = 96,
                        maxComputeInvocationsPerWorkgroup = 128, maxImmediateSize = 148;
}
// nextInChain, 4 string views (8, 24, 40, 56), backendType, adapterType, vendorID,
// deviceID, subgroupMinSize, subgroupMaxSize
namespace adapter_info {
inline constexpr size_t size = 96, vendor = 8, architecture = 24, device = 40, description = 56,
                        backendType = 72, adapterType = 76, vendorID = 80, subgroupMaxSize = 92;
}
// nextInChain, label, usage (8), dimension (4), size (Extent3D, 12), format, mipLevelCount,
// sampleCount + 4, viewFormatCount, viewFormats
namespace texture_descriptor {
inline constexpr size_t size = 80, usage = 24, dimension = 32, extent = 36, format = 48,
                        mipLevelCount = 52, sampleCount = 56, viewFormatCount = 64, viewFormats = 72;
}
// nextInChain, view, depthSlice + 4, resolveTarget, loadOp, storeOp, clearValue (4 doubles)
namespace render_pass_color_attachment {
inline constexpr size_t size = 72, view = 8, depthSlice = 16, resolveTarget = 24, loadOp = 32,
                        storeOp = 36, clearValue = 40;
}
// nextInChain, label, colorAttachmentCount, colorAttachments, depthStencilAttachment,
// occlusionQuerySet, timestampWrites
namespace render_pass_descriptor {
inline constexpr size_t size = 64, colorAttachmentCount = 24, colorAttachments = 32,
                        depthStencilAttachment = 40, occlusionQuerySet = 48, timestampWrites = 56;
}
// chain (16), codeSize + 4, code
namespace shader_source_spirv {
inline constexpr size_t size = 32, chain = 0, codeSize = 16, code = 24;
}
// nextInChain, mode + 4, callback, userdata1, userdata2
namespace buffer_map_callback_info {
inline constexpr size_t size = 40, mode = 8, callback = 16, userdata1 = 24, userdata2 = 32;
}
// nextInChain, callback, userdata1, userdata2 (no mode)
namespace uncaptured_error_callback_info {
inline constexpr size_t size = 32, callback = 8, userdata1 = 16, userdata2 = 24;
}
// nextInChain, label, requiredFeatureCount, requiredFeatures, requiredLimits,
// defaultQueue (24), deviceLostCallbackInfo (40), uncapturedErrorCallbackInfo (32)
namespace device_descriptor {
inline constexpr size_t size = 144, requiredFeatureCount = 24, requiredLimits = 40, defaultQueue = 48,
                        deviceLostCallbackInfo = 72, uncapturedErrorCallbackInfo = 112;
}
// texture, mipLevel, origin (Origin3D, 12), aspect + 4
namespace texel_copy_texture_info {
inline constexpr size_t size = 32, texture = 0, mipLevel = 8, origin = 12, aspect = 24;
}
// offset, bytesPerRow, rowsPerImage
namespace texel_copy_buffer_layout {
inline constexpr size_t size = 16, offset = 0, bytesPerRow = 8, rowsPerImage = 12;
}
// layout (16), buffer
namespace texel_copy_buffer_info {
inline constexpr size_t size = 24, layout = 0, buffer = 16;
}
// nextInChain, querySet, beginningOfPassWriteIndex, endOfPassWriteIndex
namespace pass_timestamp_writes {
inline constexpr size_t size = 24, querySet = 8, beginningOfPassWriteIndex = 16, endOfPassWriteIndex = 20;
}

}  // namespace volgraph::webgpu_abi
