// The graph's resources as Vulkan objects. Every resource gets its VkImage or
// VkBuffer first (with the usage of every pass that touches it), so the compiler
// places transients by the driver's real memory requirements; then each heap of the
// plan becomes one VkDeviceMemory and each transient is bound at its planned offset —
// resources with disjoint lifetimes really share bytes. Persistent resources get
// memory of their own.
#pragma once

#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "graph/plan.h"
#include "graph/rhi/vulkan/context.h"

namespace volgraph::vulkan {

class GraphResources {
 public:
  GraphResources(Context& context, const Graph& graph);
  ~GraphResources();
  GraphResources(const GraphResources&) = delete;
  GraphResources& operator=(const GraphResources&) = delete;

  // For compile(): the driver's size and alignment; heap class = memory type and
  // image-or-buffer (kept apart: buffer-image granularity).
  RequirementsFn requirements() const;
  // Allocates the plan's heaps and persistent memory; binds every used resource.
  void bind(const Plan& plan);

  VkImage image(uint32_t resource) const { return objects_[resource].image; }
  // VK_NULL_HANDLE for images only ever copied (views need a shader or attachment usage).
  VkImageView view(uint32_t resource) const { return objects_[resource].view; }
  // One level of a mip chain (ResourceDesc::mip_levels > 1); VK_NULL_HANDLE without a chain.
  VkImageView level_view(uint32_t resource, uint32_t level) const {
    const std::vector<VkImageView>& levels = objects_[resource].level_views;
    return level < levels.size() ? levels[level] : VK_NULL_HANDLE;
  }
  // One face of a cube at level 0 (attachments); VK_NULL_HANDLE for other kinds.
  VkImageView face_view(uint32_t resource, uint32_t face) const {
    const std::vector<VkImageView>& faces = objects_[resource].face_views;
    return face < faces.size() ? faces[face] : VK_NULL_HANDLE;
  }
  VkBuffer buffer(uint32_t resource) const { return objects_[resource].buffer; }
  // Bytes allocated for the plan's heaps (transients) and for persistent resources.
  uint64_t transient_bytes() const { return transient_bytes_; }
  uint64_t persistent_bytes() const { return persistent_bytes_; }

 private:
  struct Object {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;  // made once the image is bound: every mip level
    std::vector<VkImageView> level_views;  // a mip chain's levels, one view each
    std::vector<VkImageView> face_views;   // a cube's faces at level 0, one 2D view each
    VkBuffer buffer = VK_NULL_HANDLE;
    VkImageUsageFlags usage = 0;
    VkMemoryRequirements requirements{};
    uint32_t memory_type = 0;
  };
  void create(uint32_t resource, VkImageUsageFlags image_usage, VkBufferUsageFlags buffer_usage);
  void create_view(uint32_t resource);
  VkDeviceMemory allocate(uint64_t size, uint32_t memory_type, const std::string& name);
  void name(VkObjectType type, uint64_t handle, const std::string& text) const;

  Context& context_;
  const Graph& graph_;
  std::vector<Object> objects_;
  std::vector<VkDeviceMemory> memory_;
  uint64_t transient_bytes_ = 0;
  uint64_t persistent_bytes_ = 0;
};

}  // namespace volgraph::vulkan
