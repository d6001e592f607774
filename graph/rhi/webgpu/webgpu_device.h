// rhi::Device on WebGPU through Dawn: every interface call maps to one WebGPU call or a
// few. Barriers are ignored (WebGPU tracks usage itself); rhi's queue writes are
// WebGPU's; a buffer read back is mapped (MapAsync, then a wait on the instance).
// Buffers the device makes can always be written by write_buffer (rhi's queue write has
// no usage condition) and read back; graph resources get exactly the usages the graph
// declares (graph_resources.h), so an undeclared use is a Dawn validation error.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <webgpu/webgpu_cpp.h>

#include "graph/rhi/graph_resource_set.h"
#include "graph/rhi/rhi.h"
#include "graph/rhi/webgpu/dawn_context.h"

namespace volgraph::webgpu {

class WebGpuDevice final : public rhi::Device {
 public:
  explicit WebGpuDevice(std::unique_ptr<DawnContext> context);
  // A device on Dawn's default adapter (lavapipe's Vulkan here).
  static std::unique_ptr<WebGpuDevice> create(const DawnOptions& options = {});

  rhi::AdapterInfo info() const override { return context_->info(); }
  rhi::BufferId create_buffer(const rhi::BufferDesc& desc) override;
  rhi::TextureId create_texture(const rhi::TextureDesc& desc) override;
  rhi::TextureViewId create_view(rhi::TextureId texture) override;
  rhi::SamplerId create_sampler(const rhi::SamplerDesc& desc) override;
  rhi::ShaderModuleId create_shader_module(std::string_view label, std::span<const uint32_t> spirv) override;
  rhi::BindGroupLayoutId create_bind_group_layout(const rhi::BindGroupLayoutDesc& desc) override;
  rhi::BindGroupId create_bind_group(const rhi::BindGroupDesc& desc) override;
  rhi::ComputePipelineId create_compute_pipeline(const rhi::ComputePipelineDesc& desc) override;
  rhi::RenderPipelineId create_render_pipeline(const rhi::RenderPipelineDesc& desc) override;
  bool has_timestamps() const override { return context_->has_timestamps(); }
  bool has_dual_source_blending() const override { return context_->offers_dual_source_blending(); }
  rhi::QuerySetId create_timestamp_queries(std::string_view label, uint32_t count) override;
  std::vector<double> read_timestamps(rhi::QuerySetId queries, uint32_t first, uint32_t count) override;
  void destroy(rhi::BufferId buffer) override;
  void destroy(rhi::TextureId texture) override;
  void write_buffer(rhi::BufferId buffer, uint64_t offset, std::span<const std::byte> data) override;
  void write_texture(rhi::TextureId texture, std::span<const std::byte> texels, uint32_t mip_level = 0) override;
  std::unique_ptr<rhi::GraphResourceSet> create_graph_resources(const Graph& graph) override;
  std::unique_ptr<rhi::CommandEncoder> create_command_encoder(std::string_view label) override;
  void submit(std::unique_ptr<rhi::CommandEncoder> commands) override;
  std::vector<std::byte> read_buffer(rhi::BufferId buffer) override;

  // Dawn's uncaptured errors since the last call (DawnOptions::errors_throw off).
  std::vector<std::string> take_messages() { return context_->take_messages(); }
  DawnContext& context() const { return *context_; }

  // Objects made elsewhere (graph resources), usable through handles.
  rhi::BufferId add_buffer(wgpu::Buffer buffer, uint64_t size);
  rhi::TextureId add_texture(wgpu::Texture texture, const rhi::TextureDesc& desc);
  rhi::TextureViewId add_view(wgpu::TextureView view);

  // For the encoder.
  struct Buffer {
    wgpu::Buffer buffer;
    uint64_t size = 0;
    bool mappable = false;  // MapRead: a read-back buffer, mapped directly
  };
  struct Texture {
    wgpu::Texture texture;
    rhi::TextureDesc desc;
  };
  const Buffer& buffer(rhi::BufferId id) const { return buffers_.at(id.id); }
  const Texture& texture(rhi::TextureId id) const { return textures_.at(id.id); }
  const wgpu::TextureView& view(rhi::TextureViewId id) const { return views_.at(id.id); }
  const wgpu::ComputePipeline& pipeline(rhi::ComputePipelineId id) const { return compute_pipelines_.at(id.id); }
  const wgpu::RenderPipeline& pipeline(rhi::RenderPipelineId id) const { return render_pipelines_.at(id.id); }
  const wgpu::BindGroup& bind_group(rhi::BindGroupId id) const { return groups_.at(id.id); }
  const wgpu::QuerySet& query_set(rhi::QuerySetId id) const { return query_sets_.at(id.id); }
  // A buffer for the device's own copies (staging, read-back), never a graph resource.
  wgpu::Buffer make_buffer(std::string_view label, uint64_t size, wgpu::BufferUsage usage) const;
  wgpu::Texture make_texture(const wgpu::TextureDescriptor& descriptor) const;

 private:
  wgpu::PipelineLayout pipeline_layout(std::string_view label, const std::vector<rhi::BindGroupLayoutId>& layouts) const;
  std::vector<std::byte> map_and_read(const wgpu::Buffer& buffer, uint64_t size) const;
  void simulate_out_of_memory(std::string_view what) const;

  std::unique_ptr<DawnContext> context_;
  // Index 0 of every table is the "none" handle.
  std::vector<Buffer> buffers_{1};
  std::vector<Texture> textures_{1};
  std::vector<wgpu::TextureView> views_{1};
  std::vector<wgpu::Sampler> samplers_{1};
  std::vector<wgpu::ShaderModule> modules_{1};
  std::vector<wgpu::BindGroupLayout> layouts_{1};
  std::vector<wgpu::BindGroup> groups_{1};
  std::vector<wgpu::ComputePipeline> compute_pipelines_{1};
  std::vector<wgpu::RenderPipeline> render_pipelines_{1};
  std::vector<wgpu::QuerySet> query_sets_{1};
};

}  // namespace volgraph::webgpu
