// create_webgpu_device with Dawn (webgpu_backend.h).
#include "tools/webgpu_backend.h"

#include <cstdlib>
#include <string_view>

#include "graph/rhi/webgpu/dawn_context.h"
#include "graph/rhi/webgpu/webgpu_device.h"
#include "tools/command_line.h"

namespace volgraph {
namespace {

// VOLGRAPH_WEBGPU_ALLOW_FALLBACK=1 renders on whatever adapter Dawn offers, its Null
// backend included; unset, empty or 0 refuses those (graph/rhi/webgpu/adapter_choice.h).
bool fallback_adapter_allowed() {
  const char* value = std::getenv("VOLGRAPH_WEBGPU_ALLOW_FALLBACK");
  const std::string_view text = value ? value : "";
  if (text.empty() || text == "0") return false;
  if (text == "1") return true;
  throw UsageError("VOLGRAPH_WEBGPU_ALLOW_FALLBACK must be 1 or 0 (got \"" + std::string(text) + "\")");
}

}  // namespace

std::unique_ptr<rhi::Device> create_webgpu_device(SimulatedFault fault) {
  return webgpu::WebGpuDevice::create(
      {.errors_throw = true, .simulate = fault, .allow_fallback_adapter = fallback_adapter_allowed()});
}

std::string describe_webgpu_adapter() {
  const std::unique_ptr<webgpu::DawnContext> context = webgpu::DawnContext::create({.allow_fallback_adapter = fallback_adapter_allowed()});
  const rhi::AdapterInfo& info = context->info();
  return "webgpu: " + info.device + " — " + info.driver + "; dual-source blending (DualSourceBlending): " +
         (context->offers_dual_source_blending() ? "offered" : "not offered");
}

}  // namespace volgraph
