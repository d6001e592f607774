// out_of_memory_test.cpp — a texture too large for the device is reported as out of
// memory, naming the texture: a 16384x16384 rgba32_float texture is 4 GiB, twice
// lavapipe's maxMemoryAllocationSize (2 GiB); Dawn's Vulkan backend loses the device
// when vkBindImageMemory returns VK_ERROR_OUT_OF_DEVICE_MEMORY, which must not read as
// "device lost".
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "graph/rhi/device_error.h"
#include "graph/rhi/webgpu/webgpu_device.h"

namespace {

using volgraph::DeviceError;

TEST(WebGpuOutOfMemory, AHugeTextureIsOutOfMemoryNamingIt) {
  const std::unique_ptr<volgraph::webgpu::WebGpuDevice> device = volgraph::webgpu::WebGpuDevice::create();
  volgraph::rhi::TextureDesc desc;
  desc.label = "huge";
  desc.format = volgraph::Format::rgba32_float;
  desc.size = {16384, 16384, 1};
  desc.usage = volgraph::rhi::texture_usage::attachment | volgraph::rhi::texture_usage::copy_src;
  try {
    device->create_texture(desc);
    FAIL() << "a 4 GiB texture was created";
  } catch (const DeviceError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.kind, DeviceError::Kind::out_of_memory) << message;
    EXPECT_EQ(message.rfind("Dawn: creating texture \"huge\" (16384x16384x1, 1 mip levels): ", 0), 0u) << message;
    EXPECT_NE(message.find("VK_ERROR_OUT_OF_DEVICE_MEMORY"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

}  // namespace
