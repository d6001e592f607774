// abi_test.cpp — the declared webgpu.h structs against the hand-computed table
// (abi_table.h), and a measurement independent of any header: how many bytes the
// library writes into a WGPULimits.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <webgpu/webgpu.h>

#include "abi_table.h"
#include "dawn_device.h"

namespace tab = volgraph::webgpu_abi;

TEST(WebGpuAbi, SmallStructsAndFlags) {
  EXPECT_EQ(sizeof(WGPUFlags), 8u) << "WGPUFlags are uint64_t in this revision";
  EXPECT_EQ(sizeof(WGPUBool), 4u);
  EXPECT_EQ(sizeof(WGPUStringView), tab::string_view::size);
  EXPECT_EQ(offsetof(WGPUStringView, length), tab::string_view::length);
  EXPECT_EQ(sizeof(WGPUChainedStruct), tab::chained_struct::size);
  EXPECT_EQ(offsetof(WGPUChainedStruct, sType), tab::chained_struct::sType);
  EXPECT_EQ(sizeof(WGPUFutureWaitInfo), tab::future_wait_info::size);
  EXPECT_EQ(offsetof(WGPUFutureWaitInfo, completed), tab::future_wait_info::completed);
}

TEST(WebGpuAbi, BufferDescriptor) {
  EXPECT_EQ(sizeof(WGPUBufferDescriptor), tab::buffer_descriptor::size);
  EXPECT_EQ(offsetof(WGPUBufferDescriptor, label), tab::buffer_descriptor::label);
  EXPECT_EQ(offsetof(WGPUBufferDescriptor, usage), tab::buffer_descriptor::usage);
  EXPECT_EQ(offsetof(WGPUBufferDescriptor, size), tab::buffer_descriptor::bufferSize);
  EXPECT_EQ(offsetof(WGPUBufferDescriptor, mappedAtCreation), tab::buffer_descriptor::mappedAtCreation);
}

TEST(WebGpuAbi, BindGroupLayoutEntry) {
  namespace t = tab::bind_group_layout_entry;
  EXPECT_EQ(sizeof(WGPUBindGroupLayoutEntry), t::size);
  EXPECT_EQ(offsetof(WGPUBindGroupLayoutEntry, binding), t::binding);
  EXPECT_EQ(offsetof(WGPUBindGroupLayoutEntry, visibility), t::visibility);
  EXPECT_EQ(offsetof(WGPUBindGroupLayoutEntry, bindingArraySize), t::bindingArraySize);
  EXPECT_EQ(offsetof(WGPUBindGroupLayoutEntry, buffer), t::buffer);
  EXPECT_EQ(offsetof(WGPUBindGroupLayoutEntry, sampler), t::sampler);
  EXPECT_EQ(offsetof(WGPUBindGroupLayoutEntry, texture), t::texture);
  EXPECT_EQ(offsetof(WGPUBindGroupLayoutEntry, storageTexture), t::storageTexture);
}

TEST(WebGpuAbi, Limits) {
  namespace t = tab::limits;
  EXPECT_EQ(sizeof(WGPULimits), t::size);
  EXPECT_EQ(offsetof(WGPULimits, maxTextureDimension2D), t::maxTextureDimension2D);
  EXPECT_EQ(offsetof(WGPULimits, maxUniformBufferBindingSize), t::maxUniformBufferBindingSize);
  EXPECT_EQ(offsetof(WGPULimits, maxStorageBufferBindingSize), t::maxStorageBufferBindingSize);
  EXPECT_EQ(offsetof(WGPULimits, maxVertexBuffers), t::maxVertexBuffers);
  EXPECT_EQ(offsetof(WGPULimits, maxBufferSize), t::maxBufferSize);
  EXPECT_EQ(offsetof(WGPULimits, maxComputeInvocationsPerWorkgroup), t::maxComputeInvocationsPerWorkgroup);
  EXPECT_EQ(offsetof(WGPULimits, maxImmediateSize), t::maxImmediateSize);
}

TEST(WebGpuAbi, AdapterInfo) {
  namespace t = tab::adapter_info;
  EXPECT_EQ(sizeof(WGPUAdapterInfo), t::size);
  EXPECT_EQ(offsetof(WGPUAdapterInfo, vendor), t::vendor);
  EXPECT_EQ(offsetof(WGPUAdapterInfo, architecture), t::architecture);
  EXPECT_EQ(offsetof(WGPUAdapterInfo, device), t::device);
  EXPECT_EQ(offsetof(WGPUAdapterInfo, description), t::description);
  EXPECT_EQ(offsetof(WGPUAdapterInfo, backendType), t::backendType);
  EXPECT_EQ(offsetof(WGPUAdapterInfo, adapterType), t::adapterType);
  EXPECT_EQ(offsetof(WGPUAdapterInfo, vendorID), t::vendorID);
  EXPECT_EQ(offsetof(WGPUAdapterInfo, subgroupMaxSize), t::subgroupMaxSize);
}

TEST(WebGpuAbi, TexturesAndPasses) {
  namespace td = tab::texture_descriptor;
  EXPECT_EQ(sizeof(WGPUTextureDescriptor), td::size);
  EXPECT_EQ(offsetof(WGPUTextureDescriptor, usage), td::usage);
  EXPECT_EQ(offsetof(WGPUTextureDescriptor, dimension), td::dimension);
  EXPECT_EQ(offsetof(WGPUTextureDescriptor, size), td::extent);
  EXPECT_EQ(offsetof(WGPUTextureDescriptor, format), td::format);
  EXPECT_EQ(offsetof(WGPUTextureDescriptor, mipLevelCount), td::mipLevelCount);
  EXPECT_EQ(offsetof(WGPUTextureDescriptor, sampleCount), td::sampleCount);
  EXPECT_EQ(offsetof(WGPUTextureDescriptor, viewFormatCount), td::viewFormatCount);
  EXPECT_EQ(offsetof(WGPUTextureDescriptor, viewFormats), td::viewFormats);
  namespace ca = tab::render_pass_color_attachment;
  EXPECT_EQ(sizeof(WGPURenderPassColorAttachment), ca::size);
  EXPECT_EQ(offsetof(WGPURenderPassColorAttachment, view), ca::view);
  EXPECT_EQ(offsetof(WGPURenderPassColorAttachment, depthSlice), ca::depthSlice);
  EXPECT_EQ(offsetof(WGPURenderPassColorAttachment, resolveTarget), ca::resolveTarget);
  EXPECT_EQ(offsetof(WGPURenderPassColorAttachment, loadOp), ca::loadOp);
  EXPECT_EQ(offsetof(WGPURenderPassColorAttachment, storeOp), ca::storeOp);
  EXPECT_EQ(offsetof(WGPURenderPassColorAttachment, clearValue), ca::clearValue);
  namespace rp = tab::render_pass_descriptor;
  EXPECT_EQ(sizeof(WGPURenderPassDescriptor), rp::size);
  EXPECT_EQ(offsetof(WGPURenderPassDescriptor, colorAttachmentCount), rp::colorAttachmentCount);
  EXPECT_EQ(offsetof(WGPURenderPassDescriptor, colorAttachments), rp::colorAttachments);
  EXPECT_EQ(offsetof(WGPURenderPassDescriptor, depthStencilAttachment), rp::depthStencilAttachment);
  EXPECT_EQ(offsetof(WGPURenderPassDescriptor, occlusionQuerySet), rp::occlusionQuerySet);
  EXPECT_EQ(offsetof(WGPURenderPassDescriptor, timestampWrites), rp::timestampWrites);
  namespace ts = tab::pass_timestamp_writes;
  EXPECT_EQ(sizeof(WGPUPassTimestampWrites), ts::size);
  EXPECT_EQ(offsetof(WGPUPassTimestampWrites, querySet), ts::querySet);
  EXPECT_EQ(offsetof(WGPUPassTimestampWrites, beginningOfPassWriteIndex), ts::beginningOfPassWriteIndex);
  EXPECT_EQ(offsetof(WGPUPassTimestampWrites, endOfPassWriteIndex), ts::endOfPassWriteIndex);
}

TEST(WebGpuAbi, CopiesShadersAndCallbacks) {
  EXPECT_EQ(sizeof(WGPUTexelCopyTextureInfo), tab::texel_copy_texture_info::size);
  EXPECT_EQ(offsetof(WGPUTexelCopyTextureInfo, mipLevel), tab::texel_copy_texture_info::mipLevel);
  EXPECT_EQ(offsetof(WGPUTexelCopyTextureInfo, origin), tab::texel_copy_texture_info::origin);
  EXPECT_EQ(offsetof(WGPUTexelCopyTextureInfo, aspect), tab::texel_copy_texture_info::aspect);
  EXPECT_EQ(sizeof(WGPUTexelCopyBufferLayout), tab::texel_copy_buffer_layout::size);
  EXPECT_EQ(offsetof(WGPUTexelCopyBufferLayout, bytesPerRow), tab::texel_copy_buffer_layout::bytesPerRow);
  EXPECT_EQ(offsetof(WGPUTexelCopyBufferLayout, rowsPerImage), tab::texel_copy_buffer_layout::rowsPerImage);
  EXPECT_EQ(sizeof(WGPUTexelCopyBufferInfo), tab::texel_copy_buffer_info::size);
  EXPECT_EQ(offsetof(WGPUTexelCopyBufferInfo, buffer), tab::texel_copy_buffer_info::buffer);
  EXPECT_EQ(sizeof(WGPUShaderSourceSPIRV), tab::shader_source_spirv::size);
  EXPECT_EQ(offsetof(WGPUShaderSourceSPIRV, codeSize), tab::shader_source_spirv::codeSize);
  EXPECT_EQ(offsetof(WGPUShaderSourceSPIRV, code), tab::shader_source_spirv::code);
  EXPECT_EQ(WGPUSType_ShaderSourceSPIRV, 1) << "dawn.json: s type 'shader source SPIRV' = 1";
  namespace mc = tab::buffer_map_callback_info;
  EXPECT_EQ(sizeof(WGPUBufferMapCallbackInfo), mc::size);
  EXPECT_EQ(offsetof(WGPUBufferMapCallbackInfo, mode), mc::mode);
  EXPECT_EQ(offsetof(WGPUBufferMapCallbackInfo, callback), mc::callback);
  EXPECT_EQ(offsetof(WGPUBufferMapCallbackInfo, userdata2), mc::userdata2);
  namespace ue = tab::uncaptured_error_callback_info;
  EXPECT_EQ(sizeof(WGPUUncapturedErrorCallbackInfo), ue::size);
  EXPECT_EQ(offsetof(WGPUUncapturedErrorCallbackInfo, callback), ue::callback);
  EXPECT_EQ(offsetof(WGPUUncapturedErrorCallbackInfo, userdata2), ue::userdata2);
  namespace dd = tab::device_descriptor;
  EXPECT_EQ(sizeof(WGPUDeviceDescriptor), dd::size);
  EXPECT_EQ(offsetof(WGPUDeviceDescriptor, requiredFeatureCount), dd::requiredFeatureCount);
  EXPECT_EQ(offsetof(WGPUDeviceDescriptor, requiredLimits), dd::requiredLimits);
  EXPECT_EQ(offsetof(WGPUDeviceDescriptor, defaultQueue), dd::defaultQueue);
  EXPECT_EQ(offsetof(WGPUDeviceDescriptor, deviceLostCallbackInfo), dd::deviceLostCallbackInfo);
  EXPECT_EQ(offsetof(WGPUDeviceDescriptor, uncapturedErrorCallbackInfo), dd::uncapturedErrorCallbackInfo);
}

// Independent of the header's WGPULimits: fill a large buffer with a sentinel, let the
// library write limits into it, and see where its writing ends.
TEST(WebGpuAbi, LibraryWritesLimitsOfTheTabledSize) {
  volgraph::webgpu_test::DawnDevice dawn;
  ASSERT_NE(dawn.adapter, nullptr) << dawn.failure;
  constexpr uint8_t kSentinel = 0xA5;
  alignas(8) std::array<uint8_t, 512> bytes;
  bytes.fill(kSentinel);
  std::memset(bytes.data(), 0, sizeof(void*));  // nextInChain = nullptr
  ASSERT_EQ(wgpuAdapterGetLimits(dawn.adapter, reinterpret_cast<WGPULimits*>(bytes.data())), WGPUStatus_Success);
  size_t end = 0;
  for (size_t i = 0; i < bytes.size(); ++i) {
    if (bytes[i] != kSentinel) end = i + 1;
  }
  // The last member is a uint32 limit, so its bytes cannot all stay 0xA5 (a limit of
  // 0xA5A5A5A5 is not a thing); nothing past the struct may be touched.
  EXPECT_EQ(end, tab::limits::size);
  uint32_t max_2d = 0;
  std::memcpy(&max_2d, bytes.data() + tab::limits::maxTextureDimension2D, sizeof max_2d);
  EXPECT_GE(max_2d, 8192u) << "maxTextureDimension2D read at its tabled offset";
}
