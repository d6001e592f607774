// Synchronization2 barriers from the plan's access states (see barriers.h).
#include "graph/rhi/vulkan/barriers.h"

namespace volgraph::vulkan {

VkPipelineStageFlags2 to_vk_stages(uint32_t stages) {
  VkPipelineStageFlags2 out = VK_PIPELINE_STAGE_2_NONE;
  if (stages & stage::vertex_shader) out |= VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
  if (stages & stage::fragment_shader) out |= VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
  if (stages & stage::early_fragment_tests) out |= VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT;
  if (stages & stage::late_fragment_tests) out |= VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  if (stages & stage::color_attachment_output) out |= VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  if (stages & stage::compute_shader) out |= VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  if (stages & stage::copy) out |= VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;  // copies, clears, fills
  if (stages & stage::all_commands) out |= VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  return out;
}

VkAccessFlags2 to_vk_access(uint32_t a) {
  VkAccessFlags2 out = VK_ACCESS_2_NONE;
  if (a & access::shader_sampled_read) out |= VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
  if (a & access::shader_storage_read) out |= VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
  if (a & access::shader_storage_write) out |= VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  if (a & access::uniform_read) out |= VK_ACCESS_2_UNIFORM_READ_BIT;
  if (a & access::color_attachment_read) out |= VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT;
  if (a & access::color_attachment_write) out |= VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  if (a & access::depth_stencil_read) out |= VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
  if (a & access::depth_stencil_write) out |= VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  if (a & access::transfer_read) out |= VK_ACCESS_2_TRANSFER_READ_BIT;
  if (a & access::transfer_write) out |= VK_ACCESS_2_TRANSFER_WRITE_BIT;
  if (a & access::memory_read) out |= VK_ACCESS_2_MEMORY_READ_BIT;
  if (a & access::memory_write) out |= VK_ACCESS_2_MEMORY_WRITE_BIT;
  return out;
}

VkImageLayout to_vk(Layout layout) {
  switch (layout) {
    case Layout::undefined: return VK_IMAGE_LAYOUT_UNDEFINED;
    case Layout::general: return VK_IMAGE_LAYOUT_GENERAL;
    case Layout::shader_read_only: return VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    case Layout::color_attachment: return VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    case Layout::depth_attachment: return VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    case Layout::depth_read_only: return VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
    case Layout::transfer_src: return VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    case Layout::transfer_dst: return VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    case Layout::none: return VK_IMAGE_LAYOUT_UNDEFINED;
  }
  return VK_IMAGE_LAYOUT_UNDEFINED;
}

VkImageAspectFlags aspect_of(Format format) {
  return format_info(format).is_depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

VkImageMemoryBarrier2 image_barrier(VkImage image, Format format, const AccessState& from, const AccessState& to) {
  VkImageMemoryBarrier2 v{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  v.srcStageMask = to_vk_stages(from.stages);
  v.srcAccessMask = to_vk_access(from.access);
  v.dstStageMask = to_vk_stages(to.stages);
  v.dstAccessMask = to_vk_access(to.access);
  v.oldLayout = to_vk(from.layout);
  v.newLayout = to_vk(to.layout);
  v.srcQueueFamilyIndex = v.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  v.image = image;
  v.subresourceRange = {aspect_of(format), 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};  // every level and layer
  return v;
}

VkBufferMemoryBarrier2 buffer_barrier(VkBuffer buffer, const AccessState& from, const AccessState& to) {
  VkBufferMemoryBarrier2 v{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  v.srcStageMask = to_vk_stages(from.stages);
  v.srcAccessMask = to_vk_access(from.access);
  v.dstStageMask = to_vk_stages(to.stages);
  v.dstAccessMask = to_vk_access(to.access);
  v.srcQueueFamilyIndex = v.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  v.buffer = buffer;
  v.size = VK_WHOLE_SIZE;
  return v;
}

VkMemoryBarrier2 memory_barrier(const AccessState& from, const AccessState& to) {
  return {VK_STRUCTURE_TYPE_MEMORY_BARRIER_2, nullptr, to_vk_stages(from.stages), to_vk_access(from.access),
          to_vk_stages(to.stages), to_vk_access(to.access)};
}

void submit_barriers(VkCommandBuffer cmd, const std::vector<VkMemoryBarrier2>& globals,
                     const std::vector<VkBufferMemoryBarrier2>& buffers, const std::vector<VkImageMemoryBarrier2>& images) {
  if (globals.empty() && buffers.empty() && images.empty()) return;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = uint32_t(globals.size());
  dep.pMemoryBarriers = globals.data();
  dep.bufferMemoryBarrierCount = uint32_t(buffers.size());
  dep.pBufferMemoryBarriers = buffers.data();
  dep.imageMemoryBarrierCount = uint32_t(images.size());
  dep.pImageMemoryBarriers = images.data();
  vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace volgraph::vulkan
