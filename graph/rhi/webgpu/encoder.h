// rhi::CommandEncoder on WebGPU: one wgpu::CommandEncoder, with the compute or render
// pass open at the moment. Barriers are ignored (WebGPU orders and transitions by
// itself). What WebGPU lacks is built from what it has: a time stamp between passes is
// an empty compute pass that writes it at its beginning; update_buffer stages its bytes
// with a queue write and copies them at this point of the stream; copies between
// buffers with tightly packed rows and textures go through a staging buffer whose rows
// are 256-byte aligned, as WebGPU's copies require.
#pragma once

#include <string_view>
#include <vector>

#include <webgpu/webgpu_cpp.h>

#include "graph/rhi/rhi.h"

namespace volgraph::webgpu {

class WebGpuDevice;

class WebGpuEncoder final : public rhi::CommandEncoder {
 public:
  WebGpuEncoder(WebGpuDevice& device, std::string_view label);
  wgpu::CommandBuffer finish();

  void push_debug_group(std::string_view label) override;
  void pop_debug_group() override;
  void barrier(std::span<const rhi::ResourceBarrier>) override {}

  void begin_compute_pass(std::string_view label) override;
  void set_pipeline(rhi::ComputePipelineId pipeline) override;
  void dispatch(uint32_t x, uint32_t y, uint32_t z) override;
  void end_compute_pass() override;

  void begin_render_pass(const rhi::RenderPassDesc& desc) override;
  void set_pipeline(rhi::RenderPipelineId pipeline) override;
  void set_vertex_buffer(uint32_t slot, rhi::BufferId buffer, uint64_t offset) override;
  void set_index_buffer(rhi::BufferId buffer, rhi::IndexFormat format, uint64_t offset) override;
  void draw(uint32_t vertex_count, uint32_t instance_count, uint32_t first_vertex) override;
  void draw_indexed(uint32_t index_count, uint32_t instance_count, uint32_t first_index, int32_t base_vertex) override;
  void end_render_pass() override;

  void set_bind_group(uint32_t index, rhi::BindGroupId group) override;
  void write_timestamp(rhi::QuerySetId queries, uint32_t index) override;
  void update_buffer(rhi::BufferId buffer, uint64_t offset, std::span<const std::byte> data) override;

  void copy_buffer_to_texture(rhi::BufferId source, uint64_t offset, rhi::TextureId destination) override;
  void copy_texture_to_buffer(rhi::TextureId source, rhi::BufferId destination, uint64_t offset, uint32_t mip_level = 0) override;
  void copy_texture_to_texture(rhi::TextureId source, rhi::TextureId destination) override;
  void copy_buffer_to_buffer(rhi::BufferId source, rhi::BufferId destination, uint64_t size,
                             uint64_t destination_offset) override;

 private:
  // Where a debug group was opened: on the encoder or on the pass open then.
  enum class GroupOwner : uint8_t { encoder, compute_pass, render_pass };
  bool in_pass() const { return bool(compute_) || bool(render_); }
  // A texture's rows, tightly packed in a buffer and 256-byte aligned in a staging one.
  struct RowCopy;
  RowCopy rows_of(rhi::TextureId texture, uint32_t mip_level = 0) const;
  wgpu::TexelCopyBufferInfo copy_buffer_for(const RowCopy& rows, const wgpu::Buffer& buffer, uint64_t offset);
  void copy_rows(const wgpu::Buffer& from, uint64_t from_offset, uint64_t from_stride, const wgpu::Buffer& to,
                 uint64_t to_offset, uint64_t to_stride, const RowCopy& rows);

  WebGpuDevice& device_;
  wgpu::CommandEncoder encoder_;
  wgpu::ComputePassEncoder compute_;
  wgpu::RenderPassEncoder render_;
  std::vector<GroupOwner> groups_;
  std::vector<wgpu::Buffer> staging_;  // alive until the commands are submitted
};

}  // namespace volgraph::webgpu
