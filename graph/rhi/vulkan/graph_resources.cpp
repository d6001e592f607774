#include "graph/rhi/vulkan/graph_resources.h"

#include "graph/rhi/vulkan/barriers.h"
#include "graph/rhi/vulkan/formats.h"

namespace volgraph::vulkan {
namespace {

VkImageViewType view_type(ResourceKind kind) {
  if (kind == ResourceKind::texture3d) return VK_IMAGE_VIEW_TYPE_3D;
  return kind == ResourceKind::texture_cube ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D;
}

constexpr uint32_t heap_class(uint32_t memory_type, bool buffer) { return memory_type * 2 + (buffer ? 1 : 0); }

}  // namespace

GraphResources::GraphResources(Context& context, const Graph& graph)
    : context_(context), graph_(graph), objects_(graph.resources.size()) {
  std::vector<VkImageUsageFlags> image_usage(graph.resources.size(), 0);
  std::vector<VkBufferUsageFlags> buffer_usage(graph.resources.size(), 0);
  std::vector<VkFormatFeatureFlags> features(graph.resources.size(), 0);
  for (const GraphPass& p : graph.passes) {
    for (const ResourceUse& u : p.uses) {
      image_usage[u.resource] |= vulkan::image_usage(u.usage);
      buffer_usage[u.resource] |= vulkan::buffer_usage(u.usage);
      features[u.resource] |= format_features(u.usage);
    }
  }
  for (const ResourceVersion& o : graph.outputs) {  // read back after the frame
    image_usage[o.resource] |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    buffer_usage[o.resource] |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  }
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {  // a history pair's objects take both roles
    const uint32_t previous = graph.resources[r].previous;
    if (previous == kNone) continue;
    image_usage[r] = image_usage[previous] = image_usage[r] | image_usage[previous];
    buffer_usage[r] = buffer_usage[previous] = buffer_usage[r] | buffer_usage[previous];
    features[r] = features[previous] = features[r] | features[previous];
  }
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {
    const ResourceDesc& d = graph.resources[r].desc;
    if (d.kind != ResourceKind::buffer) {
      VkFormatProperties props;
      vkGetPhysicalDeviceFormatProperties(context.physical_device(), to_vk(d.format), &props);
      if ((props.optimalTilingFeatures & features[r]) != features[r]) {
        throw DeviceError(DeviceError::Kind::unsupported, d.name + ": " + context.info().name + " cannot use format " +
                                                              std::string(format_info(d.format).name) + " the way the graph does");
      }
    }
    create(r, image_usage[r], buffer_usage[r]);
  }
}

void GraphResources::create(uint32_t r, VkImageUsageFlags image_usage, VkBufferUsageFlags buffer_usage) {
  const ResourceDesc& d = graph_.resources[r].desc;
  Object& o = objects_[r];
  const VkDevice device = context_.device();
  if (d.kind == ResourceKind::buffer) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = std::max<uint64_t>(4, d.buffer_bytes);
    info.usage = buffer_usage ? buffer_usage : VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    check(vkCreateBuffer(device, &info, nullptr, &o.buffer), "vkCreateBuffer");
    vkGetBufferMemoryRequirements(device, o.buffer, &o.requirements);
    name(VK_OBJECT_TYPE_BUFFER, uint64_t(o.buffer), d.name);
  } else {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = d.kind == ResourceKind::texture3d ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
    info.format = to_vk(d.format);
    info.extent = {d.extent.width, d.extent.height, d.kind == ResourceKind::texture3d ? d.extent.depth : 1};
    info.mipLevels = std::max(1u, d.mip_levels);
    info.arrayLayers = array_layers(d.kind);
    if (d.kind == ResourceKind::texture_cube) info.flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = image_usage ? image_usage : VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    o.usage = info.usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(device, &info, nullptr, &o.image), "vkCreateImage");
    vkGetImageMemoryRequirements(device, o.image, &o.requirements);
    name(VK_OBJECT_TYPE_IMAGE, uint64_t(o.image), d.name);
  }
  o.memory_type = context_.memory_type(o.requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
}

RequirementsFn GraphResources::requirements() const {
  return [this](uint32_t r, const ResourceDesc& d) {
    const Object& o = objects_[r];
    return MemoryRequirements{o.requirements.size, o.requirements.alignment,
                              heap_class(o.memory_type, d.kind == ResourceKind::buffer)};
  };
}

VkDeviceMemory GraphResources::allocate(uint64_t size, uint32_t memory_type, const std::string& text) {
  VkDeviceMemory memory = context_.allocate_memory(size, memory_type, text);
  memory_.push_back(memory);
  name(VK_OBJECT_TYPE_DEVICE_MEMORY, uint64_t(memory), text);
  return memory;
}

void GraphResources::bind(const Plan& plan) {
  std::vector<VkDeviceMemory> heaps;
  for (size_t h = 0; h < plan.heaps.size(); ++h) {
    heaps.push_back(allocate(plan.heaps[h].size, plan.heaps[h].heap_class / 2, "transient heap " + std::to_string(h)));
    transient_bytes_ += plan.heaps[h].size;
  }
  const VkDevice device = context_.device();
  for (uint32_t r = 0; r < objects_.size(); ++r) {
    if (plan.lifetimes[r].first == kNone) continue;
    const Placement& p = plan.placements[r];
    const Object& o = objects_[r];
    VkDeviceMemory memory;
    uint64_t offset = 0;
    if (p.heap == kNone) {
      memory = allocate(o.requirements.size, o.memory_type, graph_.resources[r].desc.name);
      persistent_bytes_ += o.requirements.size;
    } else {
      memory = heaps[p.heap];
      offset = p.offset;
    }
    if (o.buffer) check(vkBindBufferMemory(device, o.buffer, memory, offset), "vkBindBufferMemory");
    if (!o.image) continue;
    check(vkBindImageMemory(device, o.image, memory, offset), "vkBindImageMemory");
    create_view(r);
  }
}

void GraphResources::create_view(uint32_t r) {
  const ResourceDesc& d = graph_.resources[r].desc;
  Object& o = objects_[r];
  const VkImageUsageFlags viewable = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  if (!(o.usage & viewable)) return;
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = o.image;
  info.viewType = view_type(d.kind);
  info.format = to_vk(d.format);
  const uint32_t layers = array_layers(d.kind);
  info.subresourceRange = {aspect_of(d.format), 0, std::max(1u, d.mip_levels), 0, layers};
  check(vkCreateImageView(context_.device(), &info, nullptr, &o.view), "vkCreateImageView");
  name(VK_OBJECT_TYPE_IMAGE_VIEW, uint64_t(o.view), d.name);
  // A cube's levels are always views of their own: its faces as a 2D array (storage writes).
  const bool cube = d.kind == ResourceKind::texture_cube;
  if (cube) info.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
  for (uint32_t level = 0; (d.mip_levels > 1 || cube) && level < d.mip_levels; ++level) {
    info.subresourceRange = {aspect_of(d.format), level, 1, 0, layers};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(context_.device(), &info, nullptr, &view), "vkCreateImageView");
    name(VK_OBJECT_TYPE_IMAGE_VIEW, uint64_t(view), d.name + " level " + std::to_string(level));
    o.level_views.push_back(view);
  }
  for (uint32_t face = 0; cube && face < layers; ++face) {
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.subresourceRange = {aspect_of(d.format), 0, 1, face, 1};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(context_.device(), &info, nullptr, &view), "vkCreateImageView");
    name(VK_OBJECT_TYPE_IMAGE_VIEW, uint64_t(view), d.name + " face " + std::to_string(face));
    o.face_views.push_back(view);
  }
}

void GraphResources::name(VkObjectType type, uint64_t handle, const std::string& text) const {
  context_.set_name(type, handle, text);
}

GraphResources::~GraphResources() {
  const VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  for (const Object& o : objects_) {
    if (o.view) vkDestroyImageView(device, o.view, nullptr);
    for (VkImageView level : o.level_views) vkDestroyImageView(device, level, nullptr);
    for (VkImageView face : o.face_views) vkDestroyImageView(device, face, nullptr);
    if (o.image) vkDestroyImage(device, o.image, nullptr);
    if (o.buffer) vkDestroyBuffer(device, o.buffer, nullptr);
  }
  for (VkDeviceMemory m : memory_) vkFreeMemory(device, m, nullptr);
}

}  // namespace volgraph::vulkan
