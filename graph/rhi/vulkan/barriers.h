// The plan's barriers in synchronization2 terms, recorded as the plan lists them:
// every transition before a pass in one vkCmdPipelineBarrier2.
#pragma once

#include <vulkan/vulkan.h>

#include "graph/plan.h"
#include "graph/rhi/vulkan/graph_resources.h"

namespace volgraph::vulkan {

VkPipelineStageFlags2 to_vk_stages(uint32_t stages);
VkAccessFlags2 to_vk_access(uint32_t accesses);
VkImageLayout to_vk(Layout layout);
VkImageAspectFlags aspect_of(Format format);

// Records the barriers planned before order[position].
void record_barriers(VkCommandBuffer cmd, const Graph& graph, const Plan& plan, uint32_t position,
                     const GraphResources& resources);

}  // namespace volgraph::vulkan
