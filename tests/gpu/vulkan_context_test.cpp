// Vulkan bring-up on lavapipe, validation and synchronization validation on: the
// device is what DESIGN.md says, a correctly synchronised command stream leaves the
// layer silent, and a missing barrier is reported (so a silent layer means something).
#include <cstring>

#include <gtest/gtest.h>

#include "tests/gpu/validation_messages.h"

#include "graph/rhi/vulkan/context.h"

namespace volgraph::vulkan {
namespace {

// A host-visible buffer for the fills below.
struct HostBuffer {
  HostBuffer(Context& c, VkDeviceSize size) : context(c) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    check(vkCreateBuffer(c.device(), &info, nullptr, &buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(c.device(), buffer, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex =
        c.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    check(vkAllocateMemory(c.device(), &alloc, nullptr, &memory), "vkAllocateMemory");
    check(vkBindBufferMemory(c.device(), buffer, memory, 0), "vkBindBufferMemory");
  }
  ~HostBuffer() {
    vkDestroyBuffer(context.device(), buffer, nullptr);
    vkFreeMemory(context.device(), memory, nullptr);
  }
  uint32_t word(size_t i) {
    void* p = nullptr;
    check(vkMapMemory(context.device(), memory, 0, VK_WHOLE_SIZE, 0, &p), "vkMapMemory");
    uint32_t v;
    std::memcpy(&v, static_cast<const char*>(p) + 4 * i, 4);
    vkUnmapMemory(context.device(), memory);
    return v;
  }
  Context& context;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
};

void transfer_barrier(VkCommandBuffer cmd, VkBuffer buffer) {
  VkBufferMemoryBarrier2 b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  b.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT;
  b.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  b.dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT;
  b.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.buffer = buffer;
  b.size = VK_WHOLE_SIZE;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.bufferMemoryBarrierCount = 1;
  dep.pBufferMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

TEST(VulkanContext, DefaultDeviceIsLavapipeWithVulkan13) {
  auto c = Context::create({.validation = true});
  if (c->info().name.find("llvmpipe") == std::string::npos && c->info().driver.find("Mesa") == std::string::npos) {
    GTEST_SKIP() << "no lavapipe here; the default is then the first Vulkan 1.3 device: " << c->info().name;
  }
  EXPECT_NE(c->info().name.find("llvmpipe"), std::string::npos) << c->info().name;
  EXPECT_GE(c->info().api_version, uint32_t(VK_API_VERSION_1_3));
  EXPECT_NE(c->info().driver.find("Mesa"), std::string::npos) << c->info().driver;
  EXPECT_GT(c->timestamp_period_ns(), 0.0f);
  EXPECT_TRUE(c->take_validation_messages().empty());
}

TEST(VulkanContext, SynchronisedFillsLeaveTheLayerSilent) {
  auto c = Context::create({.validation = true});
  {
    HostBuffer b(*c, 1024);
    c->submit_and_wait([&](VkCommandBuffer cmd) {
      vkCmdFillBuffer(cmd, b.buffer, 0, VK_WHOLE_SIZE, 0x11111111u);
      transfer_barrier(cmd, b.buffer);
      vkCmdFillBuffer(cmd, b.buffer, 0, 512, 0x22222222u);
    });
    EXPECT_EQ(b.word(0), 0x22222222u);
    EXPECT_EQ(b.word(200), 0x11111111u);
  }
  const auto messages = c->take_validation_messages();
  EXPECT_TRUE(messages.empty()) << joined(messages);
}

TEST(VulkanContext, AMissingBarrierIsReportedAsAHazard) {
  auto c = Context::create({.validation = true});
  {
    HostBuffer b(*c, 1024);
    c->submit_and_wait([&](VkCommandBuffer cmd) {
      vkCmdFillBuffer(cmd, b.buffer, 0, VK_WHOLE_SIZE, 0x11111111u);
      vkCmdFillBuffer(cmd, b.buffer, 0, 512, 0x22222222u);  // no barrier: write after write
    });
  }
  const std::string messages = joined(c->take_validation_messages());
  EXPECT_NE(messages.find("SYNC-HAZARD-WRITE-AFTER-WRITE"), std::string::npos) << messages;
}

TEST(VulkanContext, AnAbsentDeviceIndexIsAClearError) {
  try {
    Context::create({.validation = false, .device_index = 99});
    FAIL() << "expected a DeviceError";
  } catch (const DeviceError& e) {
    EXPECT_EQ(e.kind, DeviceError::Kind::no_device);
    EXPECT_NE(std::string(e.what()).find("--device 99"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volgraph::vulkan
