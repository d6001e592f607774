// rhi::Device on Vulkan (first slice: buffers, textures, samplers, compute pipelines,
// bind groups, copies, explicit barriers). Borrows a Context.
#pragma once

#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "graph/rhi/graph_resource_set.h"
#include "graph/rhi/rhi.h"
#include "graph/rhi/vulkan/context.h"

namespace volgraph::vulkan {

class VulkanDevice final : public rhi::Device {
 public:
  explicit VulkanDevice(Context& context);
  ~VulkanDevice() override;
  VulkanDevice(const VulkanDevice&) = delete;
  VulkanDevice& operator=(const VulkanDevice&) = delete;

  rhi::AdapterInfo info() const override;
  rhi::BufferId create_buffer(const rhi::BufferDesc& desc) override;
  rhi::TextureId create_texture(const rhi::TextureDesc& desc) override;
  rhi::TextureViewId create_view(rhi::TextureId texture) override;
  rhi::SamplerId create_sampler(const rhi::SamplerDesc& desc) override;
  rhi::ShaderModuleId create_shader_module(std::string_view label, std::span<const uint32_t> spirv) override;
  rhi::BindGroupLayoutId create_bind_group_layout(const rhi::BindGroupLayoutDesc& desc) override;
  rhi::BindGroupId create_bind_group(const rhi::BindGroupDesc& desc) override;
  rhi::ComputePipelineId create_compute_pipeline(const rhi::ComputePipelineDesc& desc) override;
  rhi::RenderPipelineId create_render_pipeline(const rhi::RenderPipelineDesc& desc) override;
  bool has_timestamps() const override { return context_.timestamp_period_ns() > 0; }
  bool has_dual_source_blending() const override { return context_.info().dual_source_blending; }
  rhi::QuerySetId create_timestamp_queries(std::string_view label, uint32_t count) override;
  std::vector<double> read_timestamps(rhi::QuerySetId queries, uint32_t first, uint32_t count) override;
  VkQueryPool query_pool(rhi::QuerySetId id) const { return query_pools_.at(id.id); }
  void destroy(rhi::BufferId buffer) override;
  void destroy(rhi::TextureId texture) override;
  void write_buffer(rhi::BufferId buffer, uint64_t offset, std::span<const std::byte> data) override;
  void write_texture(rhi::TextureId texture, std::span<const std::byte> texels, uint32_t mip_level = 0) override;
  std::unique_ptr<rhi::GraphResourceSet> create_graph_resources(const Graph& graph) override;
  std::unique_ptr<rhi::CommandEncoder> create_command_encoder(std::string_view label) override;

  // Objects another owner made (graph resources), usable through handles; never freed here.
  rhi::TextureId import_texture(VkImage image, const rhi::TextureDesc& desc);
  rhi::TextureViewId import_view(VkImageView view, rhi::TextureId texture);
  rhi::BufferId import_buffer(VkBuffer buffer, uint64_t size);
  void submit(std::unique_ptr<rhi::CommandEncoder> commands) override;
  std::vector<std::byte> read_buffer(rhi::BufferId buffer) override;

  // For the encoder.
  struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    uint64_t size = 0;
    void* mapped = nullptr;  // every buffer it makes is host-visible in this slice
    bool owned = true;
  };
  struct Texture {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    rhi::TextureDesc desc;
    bool owned = true;
    bool written = false;  // by write_texture (now in written_texture_state())
  };
  struct Pipeline {
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
  };
  const Buffer& buffer(rhi::BufferId id) const { return buffers_.at(id.id); }
  const Texture& texture(rhi::TextureId id) const { return textures_.at(id.id); }
  struct View {
    VkImageView view = VK_NULL_HANDLE;
    rhi::TextureId texture;
    bool owned = true;
  };
  const Pipeline& pipeline(rhi::ComputePipelineId id) const { return pipelines_.at(id.id); }
  const Pipeline& pipeline(rhi::RenderPipelineId id) const { return render_pipelines_.at(id.id); }
  const View& view(rhi::TextureViewId id) const { return views_.at(id.id); }
  VkDescriptorSet bind_group(rhi::BindGroupId id) const { return groups_.at(id.id).set; }
  Context& context() const { return context_; }

 private:
  struct BindGroup {
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
  };
  struct Layout {
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    std::vector<rhi::LayoutEntry> entries;
  };
  VkDeviceMemory allocate(const VkMemoryRequirements& req, bool host_visible, const std::string& label);
  VkPipelineLayout pipeline_layout(const std::vector<rhi::BindGroupLayoutId>& layouts);
  void name(VkObjectType type, uint64_t handle, const std::string& label) const;

  Context& context_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  // Index 0 of every table is the "none" handle.
  std::vector<Buffer> buffers_{1};
  std::vector<Texture> textures_{1};
  std::vector<View> views_{1};
  std::vector<VkSampler> samplers_{1};
  std::vector<VkShaderModule> modules_{1};
  std::vector<Layout> layouts_{1};
  std::vector<BindGroup> groups_{1};
  std::vector<Pipeline> pipelines_{1};
  std::vector<Pipeline> render_pipelines_{1};
  std::vector<VkQueryPool> query_pools_{1};
};

}  // namespace volgraph::vulkan
