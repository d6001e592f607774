// Which Dawn adapters volgraph renders on. Without a Vulkan driver Dawn still hands out
// an adapter: its Null backend, which accepts every call and renders nothing, so an
// image written from it is garbage. That adapter, and a CPU fallback adapter other than
// lavapipe (the CPU Vulkan driver volgraph is built for), are refused unless asked for.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <webgpu/webgpu_cpp.h>

namespace volgraph::webgpu {

// Why an adapter (its AdapterInfo's backendType, adapterType and device) is not one to
// render on by default; nullopt when it is.
std::optional<std::string> fallback_adapter_reason(wgpu::BackendType backend, wgpu::AdapterType type,
                                                   std::string_view device);

}  // namespace volgraph::webgpu
