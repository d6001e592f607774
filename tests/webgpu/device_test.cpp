// device_test.cpp — Dawn on lavapipe through the declared C API: the adapter it reports,
// its features, and a compute pipeline for composite.comp with an explicit bind group
// layout (which also checks WGPUBindGroupLayoutEntry's layout: Dawn validates every
// field of it). A wrong layout entry must raise an error: the test can fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>
#include <vector>
#include <webgpu/webgpu.h>

#include "dawn_device.h"
#include "shaders/shader_library.h"

namespace {

using volgraph::webgpu_test::DawnDevice;
using volgraph::webgpu_test::to_string;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

TEST(WebGpuDevice, AdapterIsLavapipeOnVulkan) {
  DawnDevice dawn;
  ASSERT_NE(dawn.device, nullptr) << dawn.failure;
  WGPUAdapterInfo info = {};
  ASSERT_EQ(wgpuAdapterGetInfo(dawn.adapter, &info), WGPUStatus_Success);
  const std::string vendor = to_string(info.vendor), device = to_string(info.device);
  std::printf("adapter: vendor '%s', architecture '%s', device '%s', description '%s', backend %d, type %d\n",
              vendor.c_str(), to_string(info.architecture).c_str(), device.c_str(),
              to_string(info.description).c_str(), info.backendType, info.adapterType);
  EXPECT_NE(lower(vendor).find("mesa"), std::string::npos) << vendor;
  EXPECT_NE(lower(device).find("llvmpipe"), std::string::npos) << device;
  EXPECT_EQ(info.backendType, WGPUBackendType_Vulkan);
  EXPECT_EQ(info.adapterType, WGPUAdapterType_CPU);
  wgpuAdapterInfoFreeMembers(info);

  const bool timestamps = wgpuAdapterHasFeature(dawn.adapter, WGPUFeatureName_TimestampQuery);
  std::printf("TimestampQuery: %s\n", timestamps ? "supported" : "not supported");
  WGPUSupportedFeatures features = {};
  wgpuAdapterGetFeatures(dawn.adapter, &features);
  EXPECT_GT(features.featureCount, 0u);
  const bool listed = std::find(features.features, features.features + features.featureCount,
                                WGPUFeatureName_TimestampQuery) != features.features + features.featureCount;
  EXPECT_EQ(listed, timestamps) << "HasFeature and GetFeatures agree on TimestampQuery";
  wgpuSupportedFeaturesFreeMembers(features);
  EXPECT_TRUE(dawn.events.uncaptured_errors.empty()) << dawn.events.uncaptured_errors.front();
}

// composite.comp: texture2D at 0, sampler at 1, rgba32f write-only storage image at 2,
// uniform block at 3.
WGPUBindGroupLayout composite_layout(WGPUDevice device, WGPUTextureFormat storage_format) {
  WGPUBindGroupLayoutEntry entries[4] = {};
  for (uint32_t i = 0; i < 4; ++i) {
    entries[i].binding = i;
    entries[i].visibility = WGPUShaderStage_Compute;
  }
  entries[0].texture.sampleType = WGPUTextureSampleType_UnfilterableFloat;
  entries[0].texture.viewDimension = WGPUTextureViewDimension_2D;
  entries[1].sampler.type = WGPUSamplerBindingType_NonFiltering;
  entries[2].storageTexture.access = WGPUStorageTextureAccess_WriteOnly;
  entries[2].storageTexture.format = storage_format;
  entries[2].storageTexture.viewDimension = WGPUTextureViewDimension_2D;
  entries[3].buffer.type = WGPUBufferBindingType_Uniform;
  WGPUBindGroupLayoutDescriptor descriptor = {};
  descriptor.entryCount = 4;
  descriptor.entries = entries;
  return wgpuDeviceCreateBindGroupLayout(device, &descriptor);
}

WGPUComputePipeline composite_pipeline(WGPUDevice device, WGPUBindGroupLayout layout) {
  const auto spirv = volgraph::shader_spirv("composite.comp");
  WGPUShaderSourceSPIRV source = {};
  source.chain.sType = WGPUSType_ShaderSourceSPIRV;
  source.codeSize = static_cast<uint32_t>(spirv.size());
  source.code = spirv.data();
  WGPUShaderModuleDescriptor module_descriptor = {};
  module_descriptor.nextInChain = &source.chain;
  WGPUShaderModule module = wgpuDeviceCreateShaderModule(device, &module_descriptor);
  WGPUPipelineLayoutDescriptor layout_descriptor = {};
  layout_descriptor.bindGroupLayoutCount = 1;
  layout_descriptor.bindGroupLayouts = &layout;
  WGPUPipelineLayout pipeline_layout = wgpuDeviceCreatePipelineLayout(device, &layout_descriptor);
  WGPUComputePipelineDescriptor descriptor = {};
  descriptor.layout = pipeline_layout;
  descriptor.compute.module = module;
  descriptor.compute.entryPoint = {"main", WGPU_STRLEN};
  WGPUComputePipeline pipeline = wgpuDeviceCreateComputePipeline(device, &descriptor);
  wgpuPipelineLayoutRelease(pipeline_layout);
  wgpuShaderModuleRelease(module);
  return pipeline;
}

// The uncaptured errors of creating composite.comp's pipeline with an explicit layout
// whose storage image has `storage_format`.
std::vector<std::string> composite_pipeline_errors(WGPUTextureFormat storage_format) {
  DawnDevice dawn;
  if (dawn.device == nullptr) {
    ADD_FAILURE() << "no device: " << dawn.failure;
    return {};
  }
  WGPUBindGroupLayout layout = composite_layout(dawn.device, storage_format);
  WGPUComputePipeline pipeline = composite_pipeline(dawn.device, layout);
  wgpuInstanceProcessEvents(dawn.instance);
  wgpuComputePipelineRelease(pipeline);
  wgpuBindGroupLayoutRelease(layout);
  return dawn.events.uncaptured_errors;
}

TEST(WebGpuDevice, CompositePipelineWithExplicitLayout) {
  const auto errors = composite_pipeline_errors(WGPUTextureFormat_RGBA32Float);
  EXPECT_TRUE(errors.empty()) << errors.front();
}

// Negative control: the shader's image is rgba32f, a layout saying rgba8unorm must be refused.
TEST(WebGpuDevice, MismatchedLayoutIsReported) {
  EXPECT_FALSE(composite_pipeline_errors(WGPUTextureFormat_RGBA8Unorm).empty());
}

}  // namespace
