// The device `render --backend webgpu` uses. Built from webgpu_backend.cpp when Dawn was
// found at configure time, else from webgpu_absent.cpp, which says how to get it.
#pragma once

#include <memory>
#include <string>

#include "graph/rhi/device_error.h"
#include "graph/rhi/rhi.h"

namespace volgraph {

// Dawn's errors are failures: each becomes a DeviceError at the next submission or
// read-back. Throws DeviceError (no_device, unsupported) when there is no WebGPU device.
std::unique_ptr<rhi::Device> create_webgpu_device(SimulatedFault fault);

// `volgraph devices`: the adapter Dawn offers, and whether it offers dual-source blending.
std::string describe_webgpu_adapter();

}  // namespace volgraph
