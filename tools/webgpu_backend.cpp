// create_webgpu_device with Dawn (webgpu_backend.h).
#include "tools/webgpu_backend.h"

#include "graph/rhi/webgpu/webgpu_device.h"

namespace volgraph {

std::unique_ptr<rhi::Device> create_webgpu_device(SimulatedFault fault) {
  return webgpu::WebGpuDevice::create({.errors_throw = true, .simulate = fault});
}

}  // namespace volgraph
