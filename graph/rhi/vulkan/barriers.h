// The plan's transitions (AccessState pairs) in synchronization2 terms, for the command
// encoder's barrier(): every transition given together in one vkCmdPipelineBarrier2.
#pragma once

#include <vector>

#include <vulkan/vulkan.h>

#include "graph/access.h"
#include "graph/resource.h"

namespace volgraph::vulkan {

VkPipelineStageFlags2 to_vk_stages(uint32_t stages);
VkAccessFlags2 to_vk_access(uint32_t accesses);
VkImageLayout to_vk(Layout layout);
VkImageAspectFlags aspect_of(Format format);

// One transition as a synchronization2 barrier.
VkImageMemoryBarrier2 image_barrier(VkImage image, Format format, const AccessState& from, const AccessState& to);
VkBufferMemoryBarrier2 buffer_barrier(VkBuffer buffer, const AccessState& from, const AccessState& to);
VkMemoryBarrier2 memory_barrier(const AccessState& from, const AccessState& to);  // all memory

// Records the three lists in one vkCmdPipelineBarrier2 (nothing when all are empty).
void submit_barriers(VkCommandBuffer cmd, const std::vector<VkMemoryBarrier2>& globals,
                     const std::vector<VkBufferMemoryBarrier2>& buffers, const std::vector<VkImageMemoryBarrier2>& images);

}  // namespace volgraph::vulkan
