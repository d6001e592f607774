// fallback_adapter_reason (adapter_choice.h): decided from the adapter's AdapterInfo.
#include "graph/rhi/webgpu/adapter_choice.h"

namespace volgraph::webgpu {

std::optional<std::string> fallback_adapter_reason(wgpu::BackendType backend, wgpu::AdapterType type,
                                                   std::string_view device) {
  if (backend == wgpu::BackendType::Null) {
    return "the Null backend (no Vulkan driver was found), which renders nothing";
  }
  if (type != wgpu::AdapterType::CPU) return std::nullopt;
  if (device.find("llvmpipe") != std::string_view::npos) return std::nullopt;  // lavapipe
  return "a CPU fallback adapter (\"" + std::string(device) + "\"), not lavapipe";
}

}  // namespace volgraph::webgpu
