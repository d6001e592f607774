// cpp_wrapper_test.cpp — the Dawn-style C++ API (webgpu_cpp.h) end to end on lavapipe:
// device through RequestAdapter/RequestDevice with lambdas, WriteBuffer → copy →
// MapAsync read-back, and a compute pipeline for composite.comp with the layout Dawn
// reflects from its SPIR-V. Written only against Dawn's names: it compiles unchanged
// against Dawn's own generated headers (VOLGRAPH_WEBGPU_HEADERS).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>
#include <webgpu/webgpu_cpp.h>

#include "graph/access.h"
#include "shaders/shader_library.h"

namespace {

struct Gpu {
  wgpu::Instance instance;
  wgpu::Adapter adapter;
  wgpu::Device device;
  std::vector<std::string> errors;  // uncaptured errors, filled by the device's callback
};

void open(Gpu& gpu) {
  wgpu::InstanceDescriptor instance_descriptor;
  instance_descriptor.capabilities.timedWaitAnyEnable = true;
  gpu.instance = wgpu::CreateInstance(&instance_descriptor);
  ASSERT_TRUE(gpu.instance);
  wgpu::Future adapter_future = gpu.instance.RequestAdapter(
      nullptr, wgpu::CallbackMode::WaitAnyOnly,
      [&gpu](wgpu::RequestAdapterStatus status, wgpu::Adapter adapter, wgpu::StringView) {
        if (status == wgpu::RequestAdapterStatus::Success) gpu.adapter = std::move(adapter);
      });
  ASSERT_EQ(gpu.instance.WaitAny(adapter_future, UINT64_MAX), wgpu::WaitStatus::Success);
  ASSERT_TRUE(gpu.adapter);

  wgpu::DeviceDescriptor descriptor;
  descriptor.SetUncapturedErrorCallback(
      [](const wgpu::Device&, wgpu::ErrorType, wgpu::StringView message, std::vector<std::string>* errors) {
        errors->emplace_back(std::string_view(message));
      },
      &gpu.errors);
  descriptor.SetDeviceLostCallback(wgpu::CallbackMode::AllowSpontaneous,
                                   [](const wgpu::Device&, wgpu::DeviceLostReason, wgpu::StringView) {});
  wgpu::Future device_future = gpu.adapter.RequestDevice(
      &descriptor, wgpu::CallbackMode::WaitAnyOnly,
      [&gpu](wgpu::RequestDeviceStatus status, wgpu::Device device, wgpu::StringView) {
        if (status == wgpu::RequestDeviceStatus::Success) gpu.device = std::move(device);
      });
  ASSERT_EQ(gpu.instance.WaitAny(device_future, UINT64_MAX), wgpu::WaitStatus::Success);
  ASSERT_TRUE(gpu.device);
}

TEST(WebGpuCpp, AdapterInfoAndLimits) {
  Gpu gpu;
  ASSERT_NO_FATAL_FAILURE(open(gpu));
  wgpu::AdapterInfo info;
  ASSERT_TRUE(gpu.adapter.GetInfo(&info));
  EXPECT_EQ(info.backendType, wgpu::BackendType::Vulkan);
  EXPECT_NE(std::string_view(info.device).find("llvmpipe"), std::string_view::npos);
  wgpu::Limits limits;
  ASSERT_TRUE(gpu.device.GetLimits(&limits));
  EXPECT_GE(limits.maxTextureDimension2D, 8192u);
  EXPECT_EQ(limits.maxBindGroups, 4u);
}

TEST(WebGpuCpp, WriteCopyMapReadBack) {
  Gpu gpu;
  ASSERT_NO_FATAL_FAILURE(open(gpu));
  std::vector<uint8_t> data(256);
  std::iota(data.begin(), data.end(), uint8_t{7});

  wgpu::BufferDescriptor source_descriptor{.usage = wgpu::BufferUsage::CopyDst | wgpu::BufferUsage::CopySrc,
                                           .size = data.size()};
  wgpu::Buffer source = gpu.device.CreateBuffer(&source_descriptor);
  wgpu::BufferDescriptor readback_descriptor{.usage = wgpu::BufferUsage::CopyDst | wgpu::BufferUsage::MapRead,
                                             .size = data.size()};
  wgpu::Buffer readback = gpu.device.CreateBuffer(&readback_descriptor);
  wgpu::Queue queue = gpu.device.GetQueue();
  queue.WriteBuffer(source, 0, data.data(), data.size());
  wgpu::CommandEncoder encoder = gpu.device.CreateCommandEncoder();
  encoder.CopyBufferToBuffer(source, 0, readback, 0, data.size());
  wgpu::CommandBuffer commands = encoder.Finish();
  queue.Submit(1, &commands);

  bool mapped = false;
  wgpu::Future map_future = readback.MapAsync(wgpu::MapMode::Read, 0, data.size(), wgpu::CallbackMode::WaitAnyOnly,
                                              [&mapped](wgpu::MapAsyncStatus status, wgpu::StringView) {
                                                mapped = status == wgpu::MapAsyncStatus::Success;
                                              });
  ASSERT_EQ(gpu.instance.WaitAny(map_future, UINT64_MAX), wgpu::WaitStatus::Success);
  ASSERT_TRUE(mapped);
  const auto* bytes = static_cast<const uint8_t*>(readback.GetConstMappedRange(0, data.size()));
  ASSERT_NE(bytes, nullptr);
  EXPECT_EQ(std::memcmp(bytes, data.data(), data.size()), 0);
  readback.Unmap();
  EXPECT_TRUE(gpu.errors.empty()) << gpu.errors.front();
}

TEST(WebGpuCpp, CompositePipelineFromSpirv) {
  Gpu gpu;
  ASSERT_NO_FATAL_FAILURE(open(gpu));
  const auto spirv = volgraph::shader_spirv("composite.comp");
  ASSERT_FALSE(spirv.empty());
  wgpu::ShaderSourceSPIRV source;
  source.codeSize = static_cast<uint32_t>(spirv.size());
  source.code = spirv.data();
  wgpu::ShaderModuleDescriptor module_descriptor{.nextInChain = &source, .label = "composite.comp"};
  wgpu::ShaderModule module = gpu.device.CreateShaderModule(&module_descriptor);

  gpu.device.PushErrorScope(wgpu::ErrorFilter::Validation);
  wgpu::ComputePipelineDescriptor descriptor;
  descriptor.compute.module = module;
  descriptor.compute.entryPoint = "main";
  wgpu::ComputePipeline pipeline = gpu.device.CreateComputePipeline(&descriptor);
  wgpu::BindGroupLayout layout = pipeline.GetBindGroupLayout(0);
  std::string scope_error = "(not popped)";
  wgpu::Future popped = gpu.device.PopErrorScope(
      wgpu::CallbackMode::WaitAnyOnly,
      [&scope_error](wgpu::PopErrorScopeStatus, wgpu::ErrorType type, wgpu::StringView message) {
        scope_error = type == wgpu::ErrorType::NoError ? "" : std::string(std::string_view(message));
      });
  ASSERT_EQ(gpu.instance.WaitAny(popped, UINT64_MAX), wgpu::WaitStatus::Success);
  EXPECT_EQ(scope_error, "");
  EXPECT_TRUE(pipeline);
  EXPECT_TRUE(layout);
  EXPECT_TRUE(gpu.errors.empty()) << gpu.errors.front();
}

TEST(WebGpuCpp, HandlesCountReferences) {
  Gpu gpu;
  ASSERT_NO_FATAL_FAILURE(open(gpu));
  wgpu::BufferDescriptor descriptor{.usage = wgpu::BufferUsage::Uniform, .size = 64};
  wgpu::Buffer a = gpu.device.CreateBuffer(&descriptor);
  wgpu::Buffer b = a;             // AddRef
  wgpu::Buffer c = std::move(a);  // no count change; a becomes null
  EXPECT_FALSE(a);
  EXPECT_EQ(b.Get(), c.Get());
  b = nullptr;                    // Release: c still holds it
  EXPECT_EQ(c.GetSize(), 64u);
  EXPECT_TRUE(c.GetUsage() & wgpu::BufferUsage::Uniform);
  EXPECT_TRUE(gpu.errors.empty()) << gpu.errors.front();
}

}  // namespace
