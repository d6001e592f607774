#include "graph/rhi/vulkan/vulkan_device.h"

#include <algorithm>
#include <cstring>

#include "graph/rhi/vulkan/barriers.h"
#include "graph/rhi/vulkan/formats.h"
#include "graph/rhi/vulkan/graph_resources.h"

namespace volgraph::vulkan {
namespace {

VkDescriptorType descriptor_type(rhi::BindingType type) {
  switch (type) {
    case rhi::BindingType::uniform_buffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case rhi::BindingType::storage_buffer:
    case rhi::BindingType::read_only_storage_buffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case rhi::BindingType::sampled_texture: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case rhi::BindingType::sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
    case rhi::BindingType::storage_texture: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  }
  return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
}

VkShaderStageFlags stages(uint32_t visibility) {
  VkShaderStageFlags out = 0;
  if (visibility & rhi::shader_stage::vertex) out |= VK_SHADER_STAGE_VERTEX_BIT;
  if (visibility & rhi::shader_stage::fragment) out |= VK_SHADER_STAGE_FRAGMENT_BIT;
  if (visibility & rhi::shader_stage::compute) out |= VK_SHADER_STAGE_COMPUTE_BIT;
  return out;
}

VkBufferUsageFlags buffer_usage_flags(uint32_t usage) {
  VkBufferUsageFlags out = 0;
  if (usage & rhi::buffer_usage::vertex) out |= VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
  if (usage & rhi::buffer_usage::index) out |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
  if (usage & rhi::buffer_usage::copy_src) out |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  if (usage & rhi::buffer_usage::copy_dst) out |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (usage & rhi::buffer_usage::uniform) out |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
  if (usage & rhi::buffer_usage::storage) out |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  return out;
}

VkImageUsageFlags texture_usage_flags(uint32_t usage, Format format) {
  VkImageUsageFlags out = 0;
  if (usage & rhi::texture_usage::copy_src) out |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if (usage & rhi::texture_usage::copy_dst) out |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (usage & rhi::texture_usage::sampled) out |= VK_IMAGE_USAGE_SAMPLED_BIT;
  if (usage & rhi::texture_usage::storage) out |= VK_IMAGE_USAGE_STORAGE_BIT;
  if (usage & rhi::texture_usage::attachment) {
    out |= format_info(format).is_depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  }
  return out;
}

VkFormat vertex_format(rhi::VertexFormat f) {
  switch (f) {
    case rhi::VertexFormat::float32x2: return VK_FORMAT_R32G32_SFLOAT;
    case rhi::VertexFormat::float32x3: return VK_FORMAT_R32G32B32_SFLOAT;
    case rhi::VertexFormat::float32x4: return VK_FORMAT_R32G32B32A32_SFLOAT;
  }
  return VK_FORMAT_UNDEFINED;
}

VkCompareOp compare_op(rhi::CompareFunction f) {
  switch (f) {
    case rhi::CompareFunction::never: return VK_COMPARE_OP_NEVER;
    case rhi::CompareFunction::less: return VK_COMPARE_OP_LESS;
    case rhi::CompareFunction::less_equal: return VK_COMPARE_OP_LESS_OR_EQUAL;
    case rhi::CompareFunction::greater: return VK_COMPARE_OP_GREATER;
    case rhi::CompareFunction::greater_equal: return VK_COMPARE_OP_GREATER_OR_EQUAL;
    case rhi::CompareFunction::equal: return VK_COMPARE_OP_EQUAL;
    case rhi::CompareFunction::not_equal: return VK_COMPARE_OP_NOT_EQUAL;
    case rhi::CompareFunction::always: return VK_COMPARE_OP_ALWAYS;
  }
  return VK_COMPARE_OP_ALWAYS;
}

VkRenderingAttachmentInfo attachment_info(VkImageView view, VkImageLayout layout, rhi::LoadOp load,
                                          VkAttachmentStoreOp store, VkClearValue clear) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = layout;
  a.loadOp = load == rhi::LoadOp::clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
  a.storeOp = store;
  a.clearValue = clear;
  return a;
}

VkSamplerAddressMode to_vk(rhi::AddressMode mode) {
  switch (mode) {
    case rhi::AddressMode::repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case rhi::AddressMode::mirror_repeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case rhi::AddressMode::clamp_to_edge: break;
  }
  return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
}

// One mip level of a texture, every layer (level 0: the whole texture; a cube face after face).
VkBufferImageCopy whole_level(const rhi::TextureDesc& d, uint64_t offset, uint32_t level = 0) {
  VkBufferImageCopy region{};
  region.bufferOffset = offset;
  region.imageSubresource = {aspect_of(d.format), level, 0, array_layers(d.kind)};
  const uint32_t depth = d.kind == ResourceKind::texture3d ? d.size.depth : 1;
  region.imageExtent = {std::max(1u, d.size.width >> level), std::max(1u, d.size.height >> level), std::max(1u, depth >> level)};
  return region;
}

class VulkanEncoder final : public rhi::CommandEncoder {
 public:
  VulkanEncoder(VulkanDevice& device, VkCommandBuffer cmd) : device_(device), cmd_(cmd) {}
  VkCommandBuffer command_buffer() const { return cmd_; }

  void barrier(std::span<const rhi::ResourceBarrier> barriers) override {
    std::vector<VkImageMemoryBarrier2> images;
    std::vector<VkBufferMemoryBarrier2> buffers;
    std::vector<VkMemoryBarrier2> globals;
    for (const rhi::ResourceBarrier& b : barriers) {
      if (b.texture) {
        const auto& t = device_.texture(b.texture);
        images.push_back(image_barrier(t.image, t.desc.format, b.from, b.to));
      } else if (b.buffer) {
        buffers.push_back(buffer_barrier(device_.buffer(b.buffer).buffer, b.from, b.to));
      } else {
        globals.push_back(memory_barrier(b.from, b.to));
      }
    }
    submit_barriers(cmd_, globals, buffers, images);
  }

  void push_debug_group(std::string_view label) override {
    const Context& c = device_.context();
    if (!c.has_debug_labels()) return;
    const std::string text(label);
    VkDebugUtilsLabelEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    info.pLabelName = text.c_str();
    c.begin_label(cmd_, info);
  }
  void pop_debug_group() override {
    if (device_.context().has_debug_labels()) device_.context().end_label(cmd_);
  }

  void begin_compute_pass(std::string_view label) override {
    label_ = std::string(label);
    pipeline_in_pass_ = false;
  }
  void set_pipeline(rhi::ComputePipelineId id) override {
    pipeline_ = device_.pipeline(id);
    bind_point_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    vkCmdBindPipeline(cmd_, bind_point_, pipeline_.pipeline);
    bind_pending_sets();
  }
  // As WebGPU: a bind group set before the pass's first pipeline waits for it (its layout).
  void set_bind_group(uint32_t index, rhi::BindGroupId group) override {
    const VkDescriptorSet set = device_.bind_group(group);
    if (!pipeline_in_pass_) {
      pending_sets_.emplace_back(index, set);
      return;
    }
    vkCmdBindDescriptorSets(cmd_, bind_point_, pipeline_.layout, index, 1, &set, 0, nullptr);
  }

  void begin_render_pass(const rhi::RenderPassDesc& desc) override {
    label_ = desc.label;
    pipeline_in_pass_ = false;
    std::vector<VkRenderingAttachmentInfo> colors;
    Extent size{};
    for (const rhi::ColorAttachment& c : desc.colors) {
      const auto& view = device_.view(c.view);
      size = device_.texture(view.texture).desc.size;
      VkClearValue clear{};
      std::copy(c.clear, c.clear + 4, clear.color.float32);
      colors.push_back(attachment_info(view.view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, c.load,
                                       VK_ATTACHMENT_STORE_OP_STORE, clear));
    }
    VkRenderingAttachmentInfo depth{};
    if (desc.depth.view) {
      const auto& view = device_.view(desc.depth.view);
      size = device_.texture(view.texture).desc.size;
      VkClearValue clear{};
      clear.depthStencil = {desc.depth.clear, 0};
      // A read-only depth attachment is tested, never stored (the depth_read usage).
      depth = desc.depth.read_only
                  ? attachment_info(view.view, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, rhi::LoadOp::load,
                                    VK_ATTACHMENT_STORE_OP_NONE, clear)
                  : attachment_info(view.view, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, desc.depth.load,
                                    VK_ATTACHMENT_STORE_OP_STORE, clear);
    }
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {size.width, size.height}};
    info.layerCount = 1;
    info.colorAttachmentCount = uint32_t(colors.size());
    info.pColorAttachments = colors.data();
    info.pDepthAttachment = desc.depth.view ? &depth : nullptr;
    vkCmdBeginRendering(cmd_, &info);
    // NDC +y up and row 0 at the top, as WebGPU: a viewport of negative height.
    const VkViewport viewport{0, float(size.height), float(size.width), -float(size.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {size.width, size.height}};
    vkCmdSetViewport(cmd_, 0, 1, &viewport);
    vkCmdSetScissor(cmd_, 0, 1, &scissor);
  }
  void set_pipeline(rhi::RenderPipelineId id) override {
    pipeline_ = device_.pipeline(id);
    bind_point_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
    vkCmdBindPipeline(cmd_, bind_point_, pipeline_.pipeline);
    bind_pending_sets();
  }
  void set_vertex_buffer(uint32_t slot, rhi::BufferId buffer, uint64_t offset) override {
    const VkBuffer b = device_.buffer(buffer).buffer;
    vkCmdBindVertexBuffers(cmd_, slot, 1, &b, &offset);
  }
  void set_index_buffer(rhi::BufferId buffer, rhi::IndexFormat format, uint64_t offset) override {
    vkCmdBindIndexBuffer(cmd_, device_.buffer(buffer).buffer, offset,
                         format == rhi::IndexFormat::uint16 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32);
  }
  void draw(uint32_t vertex_count, uint32_t instance_count, uint32_t first_vertex) override {
    vkCmdDraw(cmd_, vertex_count, instance_count, first_vertex, 0);
  }
  void draw_indexed(uint32_t index_count, uint32_t instance_count, uint32_t first_index, int32_t base_vertex) override {
    vkCmdDrawIndexed(cmd_, index_count, instance_count, first_index, base_vertex, 0);
  }
  void end_render_pass() override {
    vkCmdEndRendering(cmd_);
    label_.clear();
  }
  void dispatch(uint32_t x, uint32_t y, uint32_t z) override { vkCmdDispatch(cmd_, x, y, z); }
  void end_compute_pass() override { label_.clear(); }

  void write_timestamp(rhi::QuerySetId queries, uint32_t index) override {
    vkCmdWriteTimestamp2(cmd_, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, device_.query_pool(queries), index);
  }

  void copy_buffer_to_texture(rhi::BufferId source, uint64_t offset, rhi::TextureId destination) override {
    const auto& t = device_.texture(destination);
    const VkBufferImageCopy region = whole_level(t.desc, offset);
    vkCmdCopyBufferToImage(cmd_, device_.buffer(source).buffer, t.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  }
  void update_buffer(rhi::BufferId buffer, uint64_t offset, std::span<const std::byte> data) override {
    if (data.size() > 65536 || data.size() % 4 || offset % 4) {
      throw DeviceError(DeviceError::Kind::other, "update_buffer takes up to 64 KiB, in whole 4-byte words");
    }
    vkCmdUpdateBuffer(cmd_, device_.buffer(buffer).buffer, offset, data.size(), data.data());
  }

  void copy_texture_to_texture(rhi::TextureId source, rhi::TextureId destination) override {
    const auto& s = device_.texture(source);
    const auto& d = device_.texture(destination);
    const VkImageAspectFlags aspect = aspect_of(s.desc.format);
    const uint32_t layers = array_layers(s.desc.kind);
    VkImageCopy region{{aspect, 0, 0, layers}, {}, {aspect, 0, 0, layers}, {},
                       {s.desc.size.width, s.desc.size.height, s.desc.kind == ResourceKind::texture3d ? s.desc.size.depth : 1}};
    vkCmdCopyImage(cmd_, s.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, d.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                   &region);
  }
  void copy_buffer_to_buffer(rhi::BufferId source, rhi::BufferId destination, uint64_t size,
                             uint64_t destination_offset) override {
    const VkBufferCopy region{0, destination_offset, size};
    vkCmdCopyBuffer(cmd_, device_.buffer(source).buffer, device_.buffer(destination).buffer, 1, &region);
  }
  void copy_texture_to_buffer(rhi::TextureId source, rhi::BufferId destination, uint64_t offset, uint32_t mip_level = 0) override {
    const auto& t = device_.texture(source);
    const VkBufferImageCopy region = whole_level(t.desc, offset, mip_level);
    vkCmdCopyImageToBuffer(cmd_, t.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, device_.buffer(destination).buffer, 1, &region);
  }

 private:
  // The sets bound before the pass's first pipeline, with its layout; later ones bind at once.
  void bind_pending_sets() {
    pipeline_in_pass_ = true;
    for (const auto& [index, set] : pending_sets_) vkCmdBindDescriptorSets(cmd_, bind_point_, pipeline_.layout, index, 1, &set, 0, nullptr);
    pending_sets_.clear();
  }

  VulkanDevice& device_;
  VkCommandBuffer cmd_;
  VulkanDevice::Pipeline pipeline_;
  bool pipeline_in_pass_ = false;  // a pipeline set since the pass began: its layout binds the sets
  std::vector<std::pair<uint32_t, VkDescriptorSet>> pending_sets_;
  VkPipelineBindPoint bind_point_ = VK_PIPELINE_BIND_POINT_COMPUTE;
  std::string label_;
};

}  // namespace

VulkanDevice::VulkanDevice(Context& context) : context_(context) {
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pool.queueFamilyIndex = context.queue_family();
  check(vkCreateCommandPool(context.device(), &pool, nullptr, &pool_), "vkCreateCommandPool");
}

VulkanDevice::~VulkanDevice() {
  const VkDevice d = context_.device();
  vkDeviceWaitIdle(d);
  for (const auto* table : {&pipelines_, &render_pipelines_}) {
    for (const Pipeline& p : *table) {
      if (p.pipeline) vkDestroyPipeline(d, p.pipeline, nullptr);
      if (p.layout) vkDestroyPipelineLayout(d, p.layout, nullptr);
    }
  }
  for (VkQueryPool q : query_pools_) {
    if (q) vkDestroyQueryPool(d, q, nullptr);
  }
  for (const BindGroup& g : groups_) {
    if (g.pool) vkDestroyDescriptorPool(d, g.pool, nullptr);
  }
  for (const Layout& l : layouts_) {
    if (l.layout) vkDestroyDescriptorSetLayout(d, l.layout, nullptr);
  }
  for (VkShaderModule m : modules_) {
    if (m) vkDestroyShaderModule(d, m, nullptr);
  }
  for (VkSampler s : samplers_) {
    if (s) vkDestroySampler(d, s, nullptr);
  }
  for (const View& v : views_) {
    if (v.view && v.owned) vkDestroyImageView(d, v.view, nullptr);
  }
  for (const Texture& t : textures_) {
    if (t.image && t.owned) vkDestroyImage(d, t.image, nullptr);
    if (t.memory) vkFreeMemory(d, t.memory, nullptr);
  }
  for (const Buffer& b : buffers_) {
    if (b.buffer && b.owned) vkDestroyBuffer(d, b.buffer, nullptr);
    if (b.memory) vkFreeMemory(d, b.memory, nullptr);
  }
  vkDestroyCommandPool(d, pool_, nullptr);
}

rhi::AdapterInfo VulkanDevice::info() const { return {"vulkan", context_.info().name, context_.info().driver}; }

void VulkanDevice::name(VkObjectType type, uint64_t handle, const std::string& label) const {
  context_.set_name(type, handle, label);
}

VkDeviceMemory VulkanDevice::allocate(const VkMemoryRequirements& req, bool host_visible, const std::string& label) {
  const VkMemoryPropertyFlags wanted = host_visible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                                    : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  return context_.allocate_memory(req.size, context_.memory_type(req.memoryTypeBits, wanted), label);
}

rhi::BufferId VulkanDevice::create_buffer(const rhi::BufferDesc& desc) {
  Buffer b;
  b.size = desc.size;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = std::max<uint64_t>(4, desc.size);
  info.usage = buffer_usage_flags(desc.usage);
  check(vkCreateBuffer(context_.device(), &info, nullptr, &b.buffer), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(context_.device(), b.buffer, &req);
  b.memory = allocate(req, true, desc.label);
  check(vkBindBufferMemory(context_.device(), b.buffer, b.memory, 0), "vkBindBufferMemory");
  check(vkMapMemory(context_.device(), b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  name(VK_OBJECT_TYPE_BUFFER, uint64_t(b.buffer), desc.label);
  buffers_.push_back(b);
  return {uint32_t(buffers_.size() - 1)};
}

rhi::TextureId VulkanDevice::create_texture(const rhi::TextureDesc& desc) {
  Texture t;
  t.desc = desc;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = desc.kind == ResourceKind::texture3d ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
  info.format = to_vk(desc.format);
  info.extent = {desc.size.width, desc.size.height, desc.kind == ResourceKind::texture3d ? desc.size.depth : 1};
  info.mipLevels = std::max(1u, desc.mip_levels);
  info.arrayLayers = array_layers(desc.kind);
  if (desc.kind == ResourceKind::texture_cube) info.flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = texture_usage_flags(desc.usage, desc.format);
  check(vkCreateImage(context_.device(), &info, nullptr, &t.image), "vkCreateImage");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(context_.device(), t.image, &req);
  t.memory = allocate(req, false, desc.label);
  check(vkBindImageMemory(context_.device(), t.image, t.memory, 0), "vkBindImageMemory");
  name(VK_OBJECT_TYPE_IMAGE, uint64_t(t.image), desc.label);
  textures_.push_back(t);
  return {uint32_t(textures_.size() - 1)};
}

rhi::TextureViewId VulkanDevice::create_view(rhi::TextureId id) {
  const Texture& t = textures_.at(id.id);
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = t.image;
  info.viewType = t.desc.kind == ResourceKind::texture3d      ? VK_IMAGE_VIEW_TYPE_3D
                  : t.desc.kind == ResourceKind::texture_cube ? VK_IMAGE_VIEW_TYPE_CUBE
                                                              : VK_IMAGE_VIEW_TYPE_2D;
  info.format = to_vk(t.desc.format);
  info.subresourceRange = {aspect_of(t.desc.format), 0, std::max(1u, t.desc.mip_levels), 0, array_layers(t.desc.kind)};
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(context_.device(), &info, nullptr, &view), "vkCreateImageView");
  name(VK_OBJECT_TYPE_IMAGE_VIEW, uint64_t(view), t.desc.label);
  views_.push_back({view, id});
  return {uint32_t(views_.size() - 1)};
}

rhi::SamplerId VulkanDevice::create_sampler(const rhi::SamplerDesc& desc) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = info.minFilter = desc.filter == rhi::Filter::linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  info.mipmapMode = desc.mip_filter == rhi::Filter::linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.maxLod = VK_LOD_CLAMP_NONE;
  info.addressModeU = to_vk(desc.address_u);
  info.addressModeV = to_vk(desc.address_v);
  info.addressModeW = to_vk(desc.address_w);
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(context_.device(), &info, nullptr, &sampler), "vkCreateSampler");
  name(VK_OBJECT_TYPE_SAMPLER, uint64_t(sampler), desc.label);
  samplers_.push_back(sampler);
  return {uint32_t(samplers_.size() - 1)};
}

rhi::ShaderModuleId VulkanDevice::create_shader_module(std::string_view label, std::span<const uint32_t> spirv) {
  if (spirv.empty()) throw DeviceError(DeviceError::Kind::other, "shader module " + std::string(label) + " has no SPIR-V");
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  check(vkCreateShaderModule(context_.device(), &info, nullptr, &module), "vkCreateShaderModule");
  name(VK_OBJECT_TYPE_SHADER_MODULE, uint64_t(module), std::string(label));
  modules_.push_back(module);
  return {uint32_t(modules_.size() - 1)};
}

rhi::BindGroupLayoutId VulkanDevice::create_bind_group_layout(const rhi::BindGroupLayoutDesc& desc) {
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const rhi::LayoutEntry& e : desc.entries) {
    bindings.push_back({e.binding, descriptor_type(e.type), 1, stages(e.visibility), nullptr});
  }
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = uint32_t(bindings.size());
  info.pBindings = bindings.data();
  Layout l;
  l.entries = desc.entries;
  check(vkCreateDescriptorSetLayout(context_.device(), &info, nullptr, &l.layout), "vkCreateDescriptorSetLayout");
  name(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, uint64_t(l.layout), desc.label);
  layouts_.push_back(l);
  return {uint32_t(layouts_.size() - 1)};
}

rhi::BindGroupId VulkanDevice::create_bind_group(const rhi::BindGroupDesc& desc) {
  const Layout& layout = layouts_.at(desc.layout.id);
  std::vector<VkDescriptorPoolSize> sizes;
  for (const rhi::LayoutEntry& e : layout.entries) sizes.push_back({descriptor_type(e.type), 1});
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = uint32_t(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  BindGroup g;
  check(vkCreateDescriptorPool(context_.device(), &pool_info, nullptr, &g.pool), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = g.pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout.layout;
  check(vkAllocateDescriptorSets(context_.device(), &alloc, &g.set), "vkAllocateDescriptorSets");
  name(VK_OBJECT_TYPE_DESCRIPTOR_SET, uint64_t(g.set), desc.label);

  std::vector<VkDescriptorImageInfo> images(desc.entries.size());
  std::vector<VkDescriptorBufferInfo> buffers(desc.entries.size());
  std::vector<VkWriteDescriptorSet> writes;
  for (size_t i = 0; i < desc.entries.size(); ++i) {
    const rhi::BindGroupEntry& e = desc.entries[i];
    rhi::BindingType type = rhi::BindingType::uniform_buffer;
    for (const rhi::LayoutEntry& le : layout.entries) {
      if (le.binding == e.binding) type = le.type;
    }
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = g.set;
    w.dstBinding = e.binding;
    w.descriptorCount = 1;
    w.descriptorType = descriptor_type(type);
    if (type == rhi::BindingType::sampler) {
      images[i] = {samplers_.at(e.sampler.id), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
      w.pImageInfo = &images[i];
    } else if (type == rhi::BindingType::sampled_texture || type == rhi::BindingType::storage_texture) {
      // The layouts the plan puts them in for these uses (graph/access.cpp).
      const VkImageLayout layout_in_use = type == rhi::BindingType::sampled_texture
                                              ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                              : VK_IMAGE_LAYOUT_GENERAL;
      images[i] = {VK_NULL_HANDLE, views_.at(e.view.id).view, layout_in_use};
      w.pImageInfo = &images[i];
    } else {
      buffers[i] = {buffers_.at(e.buffer.id).buffer, e.offset, e.size ? e.size : VK_WHOLE_SIZE};
      w.pBufferInfo = &buffers[i];
    }
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(context_.device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
  groups_.push_back(g);
  return {uint32_t(groups_.size() - 1)};
}

VkPipelineLayout VulkanDevice::pipeline_layout(const std::vector<rhi::BindGroupLayoutId>& layouts) {
  std::vector<VkDescriptorSetLayout> sets;
  for (rhi::BindGroupLayoutId l : layouts) sets.push_back(layouts_.at(l.id).layout);
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = uint32_t(sets.size());
  info.pSetLayouts = sets.data();
  VkPipelineLayout layout = VK_NULL_HANDLE;
  check(vkCreatePipelineLayout(context_.device(), &info, nullptr, &layout), "vkCreatePipelineLayout");
  return layout;
}

rhi::ComputePipelineId VulkanDevice::create_compute_pipeline(const rhi::ComputePipelineDesc& desc) {
  Pipeline p;
  p.layout = pipeline_layout(desc.layouts);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = modules_.at(desc.module.id);
  info.stage.pName = desc.entry_point.c_str();
  info.layout = p.layout;
  check(vkCreateComputePipelines(context_.device(), VK_NULL_HANDLE, 1, &info, nullptr, &p.pipeline), "vkCreateComputePipelines");
  name(VK_OBJECT_TYPE_PIPELINE, uint64_t(p.pipeline), desc.label);
  pipelines_.push_back(p);
  return {uint32_t(pipelines_.size() - 1)};
}

rhi::RenderPipelineId VulkanDevice::create_render_pipeline(const rhi::RenderPipelineDesc& desc) {
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
  stage.module = modules_.at(desc.vertex_module.id);
  stage.pName = desc.vertex_entry.c_str();
  stages.push_back(stage);
  if (desc.fragment_module) {
    stage.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stage.module = modules_.at(desc.fragment_module.id);
    stage.pName = desc.fragment_entry.c_str();
    stages.push_back(stage);
  }
  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
  for (uint32_t b = 0; b < desc.vertex_buffers.size(); ++b) {
    bindings.push_back({b, desc.vertex_buffers[b].stride, VK_VERTEX_INPUT_RATE_VERTEX});
    for (const rhi::VertexAttribute& a : desc.vertex_buffers[b].attributes) {
      attributes.push_back({a.location, b, vertex_format(a.format), a.offset});
    }
  }
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex_input.vertexBindingDescriptionCount = uint32_t(bindings.size());
  vertex_input.pVertexBindingDescriptions = bindings.data();
  vertex_input.vertexAttributeDescriptionCount = uint32_t(attributes.size());
  vertex_input.pVertexAttributeDescriptions = attributes.data();
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = desc.cull == rhi::CullMode::back    ? VK_CULL_MODE_BACK_BIT
                    : desc.cull == rhi::CullMode::front ? VK_CULL_MODE_FRONT_BIT
                                                        : VK_CULL_MODE_NONE;
  raster.frontFace = desc.front_counter_clockwise ? VK_FRONT_FACE_COUNTER_CLOCKWISE : VK_FRONT_FACE_CLOCKWISE;
  raster.depthBiasEnable = desc.depth.bias_constant != 0 || desc.depth.bias_slope != 0;
  raster.depthBiasConstantFactor = desc.depth.bias_constant;
  raster.depthBiasSlopeFactor = desc.depth.bias_slope;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = desc.depth.format != Format::undefined;
  depth.depthWriteEnable = depth.depthTestEnable && desc.depth.write;
  depth.depthCompareOp = compare_op(desc.depth.compare);
  std::vector<VkPipelineColorBlendAttachmentState> blends;
  std::vector<VkFormat> color_formats;
  for (const rhi::ColorTargetState& c : desc.colors) {
    VkPipelineColorBlendAttachmentState b{};
    b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    if (c.blend == rhi::BlendMode::additive) {
      b.blendEnable = VK_TRUE;
      b.srcColorBlendFactor = b.dstColorBlendFactor = b.srcAlphaBlendFactor = b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
      b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    if (c.blend == rhi::BlendMode::multiply) {  // dst × src
      b.blendEnable = VK_TRUE;
      b.srcColorBlendFactor = b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
      b.dstColorBlendFactor = VK_BLEND_FACTOR_SRC_COLOR;
      b.dstAlphaBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
      b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    if (c.blend == rhi::BlendMode::premultiplied_over) {  // src + dst × (1 − src alpha)
      b.blendEnable = VK_TRUE;
      b.srcColorBlendFactor = b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
      b.dstColorBlendFactor = b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
      b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    if (c.blend == rhi::BlendMode::premultiplied_under) {  // dst + src × (1 − dst alpha)
      b.blendEnable = VK_TRUE;
      b.srcColorBlendFactor = b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
      b.dstColorBlendFactor = b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
      b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    if (c.blend == rhi::BlendMode::source_plus_dest_times_source1) {  // src0 + dst × src1
      b.blendEnable = VK_TRUE;
      b.srcColorBlendFactor = b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
      b.dstColorBlendFactor = VK_BLEND_FACTOR_SRC1_COLOR;
      b.dstAlphaBlendFactor = VK_BLEND_FACTOR_SRC1_ALPHA;
      b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    blends.push_back(b);
    color_formats.push_back(to_vk(c.format));
  }
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = uint32_t(blends.size());
  blend.pAttachments = blends.data();
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = uint32_t(color_formats.size());
  rendering.pColorAttachmentFormats = color_formats.data();
  rendering.depthAttachmentFormat = to_vk(desc.depth.format);

  Pipeline p;
  p.layout = pipeline_layout(desc.layouts);
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
  info.stageCount = uint32_t(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = p.layout;
  check(vkCreateGraphicsPipelines(context_.device(), VK_NULL_HANDLE, 1, &info, nullptr, &p.pipeline), "vkCreateGraphicsPipelines");
  name(VK_OBJECT_TYPE_PIPELINE, uint64_t(p.pipeline), desc.label);
  render_pipelines_.push_back(p);
  return {uint32_t(render_pipelines_.size() - 1)};
}

rhi::QuerySetId VulkanDevice::create_timestamp_queries(std::string_view label, uint32_t count) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = count;
  VkQueryPool pool = VK_NULL_HANDLE;
  check(vkCreateQueryPool(context_.device(), &info, nullptr, &pool), "vkCreateQueryPool");
  vkResetQueryPool(context_.device(), pool, 0, count);  // host reset (Vulkan 1.2 hostQueryReset)
  name(VK_OBJECT_TYPE_QUERY_POOL, uint64_t(pool), std::string(label));
  query_pools_.push_back(pool);
  return {uint32_t(query_pools_.size() - 1)};
}

std::vector<double> VulkanDevice::read_timestamps(rhi::QuerySetId id, uint32_t first, uint32_t count) {
  check(vkQueueWaitIdle(context_.queue()), "vkQueueWaitIdle");
  std::vector<uint64_t> ticks(count);
  check(vkGetQueryPoolResults(context_.device(), query_pools_.at(id.id), first, count, count * sizeof(uint64_t),
                              ticks.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults");
  vkResetQueryPool(context_.device(), query_pools_.at(id.id), first, count);  // ready for the next frame
  std::vector<double> ns(count);
  for (uint32_t i = 0; i < count; ++i) ns[i] = double(ticks[i]) * double(context_.timestamp_period_ns());
  return ns;
}

void VulkanDevice::destroy(rhi::BufferId id) {
  Buffer& b = buffers_.at(id.id);
  vkDeviceWaitIdle(context_.device());
  vkDestroyBuffer(context_.device(), b.buffer, nullptr);
  vkFreeMemory(context_.device(), b.memory, nullptr);
  b = Buffer{};
}

void VulkanDevice::destroy(rhi::TextureId id) {
  Texture& t = textures_.at(id.id);
  vkDeviceWaitIdle(context_.device());
  vkDestroyImage(context_.device(), t.image, nullptr);
  vkFreeMemory(context_.device(), t.memory, nullptr);
  t = Texture{};
}

void VulkanDevice::write_buffer(rhi::BufferId id, uint64_t offset, std::span<const std::byte> data) {
  const Buffer& b = buffers_.at(id.id);
  if (offset + data.size() > b.size) throw DeviceError(DeviceError::Kind::other, "write_buffer past the end of the buffer");
  std::memcpy(static_cast<char*>(b.mapped) + offset, data.data(), data.size());  // host-coherent; the next submit sees it
}

// Level by level, each a transfer write of its own between two barriers; the first
// write discards the texture's contents, later ones keep the levels written before.
void VulkanDevice::write_texture(rhi::TextureId id, std::span<const std::byte> texels, uint32_t mip_level) {
  const Texture& t = textures_.at(id.id);
  if (mip_level >= std::max(1u, t.desc.mip_levels)) {
    throw DeviceError(DeviceError::Kind::other, "write_texture: " + t.desc.label + " has no mip level " + std::to_string(mip_level));
  }
  const rhi::BufferId staging = create_buffer({t.desc.label + " upload", texels.size(), rhi::buffer_usage::copy_src});
  write_buffer(staging, 0, texels);
  auto encoder = create_command_encoder("write_texture");
  const AccessState copy_written{stage::copy, access::transfer_write, volgraph::Layout::transfer_dst};
  const AccessState before = t.written ? written_texture_state() : AccessState{};
  const rhi::ResourceBarrier to_copy{id, {}, before, copy_written};
  encoder->barrier({&to_copy, 1});
  const VkBufferImageCopy region = whole_level(t.desc, 0, mip_level);
  vkCmdCopyBufferToImage(static_cast<VulkanEncoder&>(*encoder).command_buffer(), buffer(staging).buffer, t.image,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  const rhi::ResourceBarrier to_sampled{id, {}, copy_written, written_texture_state()};
  encoder->barrier({&to_sampled, 1});
  submit(std::move(encoder));
  textures_.at(id.id).written = true;
  destroy(staging);
}

rhi::TextureId VulkanDevice::import_texture(VkImage image, const rhi::TextureDesc& desc) {
  textures_.push_back({image, VK_NULL_HANDLE, desc, false});
  return {uint32_t(textures_.size() - 1)};
}

rhi::TextureViewId VulkanDevice::import_view(VkImageView view, rhi::TextureId texture) {
  views_.push_back({view, texture, false});
  return {uint32_t(views_.size() - 1)};
}

rhi::BufferId VulkanDevice::import_buffer(VkBuffer buffer, uint64_t size) {
  buffers_.push_back({buffer, VK_NULL_HANDLE, size, nullptr, false});
  return {uint32_t(buffers_.size() - 1)};
}

namespace {

// GraphResources (placed in the plan's heaps) behind the interface's handles.
class VulkanGraphResources final : public rhi::GraphResourceSet {
 public:
  VulkanGraphResources(VulkanDevice& device, const Graph& graph) : device_(device), graph_(graph), resources_(device.context(), graph) {}

  RequirementsFn requirements() const override { return resources_.requirements(); }

  void bind(const Plan& plan) override {
    resources_.bind(plan);
    textures_.assign(graph_.resources.size(), {});
    views_.assign(graph_.resources.size(), {});
    level_views_.assign(graph_.resources.size(), {});
    face_views_.assign(graph_.resources.size(), {});
    buffers_.assign(graph_.resources.size(), {});
    for (uint32_t r = 0; r < graph_.resources.size(); ++r) {
      if (plan.lifetimes[r].first == kNone) continue;
      const ResourceDesc& d = graph_.resources[r].desc;
      if (d.kind == ResourceKind::buffer) {
        buffers_[r] = device_.import_buffer(resources_.buffer(r), d.buffer_bytes);
        continue;
      }
      textures_[r] = device_.import_texture(resources_.image(r), {d.name, d.kind, d.format, d.extent, 0, d.mip_levels});
      if (resources_.view(r)) views_[r] = device_.import_view(resources_.view(r), textures_[r]);
      for (uint32_t level = 0; resources_.level_view(r, level); ++level) {
        level_views_[r].push_back(device_.import_view(resources_.level_view(r, level), textures_[r]));
      }
      for (uint32_t face = 0; resources_.face_view(r, face); ++face) {
        face_views_[r].push_back(device_.import_view(resources_.face_view(r, face), textures_[r]));
      }
    }
  }

  rhi::TextureId texture(uint32_t r) const override { return textures_.at(r); }
  rhi::TextureViewId view(uint32_t r) const override { return views_.at(r); }
  rhi::TextureViewId level_view(uint32_t r, uint32_t level) const override {
    const std::vector<rhi::TextureViewId>& levels = level_views_.at(r);
    return levels.empty() && level == 0 ? views_.at(r) : levels.at(level);
  }
  rhi::TextureViewId face_view(uint32_t r, uint32_t face) const override {
    const std::vector<rhi::TextureViewId>& faces = face_views_.at(r);
    return face < faces.size() ? faces[face] : rhi::TextureViewId{};
  }
  rhi::BufferId buffer(uint32_t r) const override { return buffers_.at(r); }
  void swap(uint32_t a, uint32_t b) override {
    std::swap(textures_.at(a), textures_.at(b));
    std::swap(views_.at(a), views_.at(b));
    std::swap(level_views_.at(a), level_views_.at(b));
    std::swap(face_views_.at(a), face_views_.at(b));
    std::swap(buffers_.at(a), buffers_.at(b));
  }

 private:
  VulkanDevice& device_;
  const Graph& graph_;
  GraphResources resources_;
  std::vector<rhi::TextureId> textures_;
  std::vector<rhi::TextureViewId> views_;
  std::vector<std::vector<rhi::TextureViewId>> level_views_;  // a mip chain's levels
  std::vector<std::vector<rhi::TextureViewId>> face_views_;   // a cube's faces
  std::vector<rhi::BufferId> buffers_;
};

}  // namespace

std::unique_ptr<rhi::GraphResourceSet> VulkanDevice::create_graph_resources(const Graph& graph) {
  return std::make_unique<VulkanGraphResources>(*this, graph);
}

std::unique_ptr<rhi::CommandEncoder> VulkanDevice::create_command_encoder(std::string_view) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(context_.device(), &alloc, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  return std::make_unique<VulkanEncoder>(*this, cmd);
}

void VulkanDevice::submit(std::unique_ptr<rhi::CommandEncoder> commands) {
  const VkCommandBuffer cmd = static_cast<VulkanEncoder&>(*commands).command_buffer();
  // Device writes become visible to the host (buffers are mapped) once this completes.
  VkMemoryBarrier2 to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2, nullptr, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                           VK_ACCESS_2_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT};
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &to_host;
  vkCmdPipelineBarrier2(cmd, &dep);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  const VkResult result = context_.submit_recorded(cmd);
  vkFreeCommandBuffers(context_.device(), pool_, 1, &cmd);
  check(result, "vkQueueSubmit2");
}

std::vector<std::byte> VulkanDevice::read_buffer(rhi::BufferId id) {
  const Buffer& b = buffers_.at(id.id);
  check(vkQueueWaitIdle(context_.queue()), "vkQueueWaitIdle");
  const auto* begin = static_cast<const std::byte*>(b.mapped);
  return {begin, begin + b.size};
}

}  // namespace volgraph::vulkan
