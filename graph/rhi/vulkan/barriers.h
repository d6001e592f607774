// The plan's barriers in synchronization2 terms, recorded as the plan lists them:
// every transition before a pass in one vkCmdPipelineBarrier2.
#pragma once

#include <vector>

#include <vulkan/vulkan.h>

#include "graph/plan.h"
#include "graph/rhi/vulkan/graph_resources.h"

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

// Records the barriers planned before order[position].
void record_barriers(VkCommandBuffer cmd, const Graph& graph, const Plan& plan, uint32_t position,
                     const GraphResources& resources);

}  // namespace volgraph::vulkan
