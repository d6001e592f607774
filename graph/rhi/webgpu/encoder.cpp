// WebGpuEncoder (encoder.h): rhi commands as WebGPU commands.
#include "graph/rhi/webgpu/encoder.h"

#include "graph/rhi/device_error.h"
#include "graph/rhi/webgpu/formats.h"
#include "graph/rhi/webgpu/webgpu_device.h"

namespace volgraph::webgpu {
namespace {

constexpr uint32_t kCopyRowAlignment = 256;  // WebGPU: bytesPerRow of buffer↔texture copies

wgpu::Color color_of(const float (&c)[4]) { return {c[0], c[1], c[2], c[3]}; }

wgpu::LoadOp load_op(rhi::LoadOp op) { return op == rhi::LoadOp::clear ? wgpu::LoadOp::Clear : wgpu::LoadOp::Load; }

wgpu::RenderPassDepthStencilAttachment depth_attachment(const wgpu::TextureView& view, const rhi::DepthAttachment& d) {
  wgpu::RenderPassDepthStencilAttachment out;
  out.view = view;
  if (d.read_only) {  // tested, never written: no load or store operations
    out.depthReadOnly = true;
    return out;
  }
  out.depthLoadOp = load_op(d.load);
  out.depthStoreOp = wgpu::StoreOp::Store;
  out.depthClearValue = d.clear;
  return out;
}

}  // namespace

struct WebGpuEncoder::RowCopy {
  wgpu::TexelCopyTextureInfo texture;
  wgpu::Extent3D extent;
  uint32_t row_bytes = 0;     // tightly packed
  uint32_t padded_bytes = 0;  // 256-byte aligned
  uint32_t rows = 0;          // height × depth
};

WebGpuEncoder::WebGpuEncoder(WebGpuDevice& device, std::string_view label) : device_(device) {
  wgpu::CommandEncoderDescriptor descriptor;
  descriptor.label = label;
  encoder_ = device.context().device().CreateCommandEncoder(&descriptor);
}

wgpu::CommandBuffer WebGpuEncoder::finish() { return encoder_.Finish(); }

void WebGpuEncoder::push_debug_group(std::string_view label) {
  const GroupOwner owner = compute_ ? GroupOwner::compute_pass : render_ ? GroupOwner::render_pass : GroupOwner::encoder;
  if (owner == GroupOwner::compute_pass) compute_.PushDebugGroup(label);
  if (owner == GroupOwner::render_pass) render_.PushDebugGroup(label);
  if (owner == GroupOwner::encoder) encoder_.PushDebugGroup(label);
  groups_.push_back(owner);
}

void WebGpuEncoder::pop_debug_group() {
  if (groups_.empty()) return;
  const GroupOwner owner = groups_.back();
  groups_.pop_back();
  if (owner == GroupOwner::compute_pass && compute_) compute_.PopDebugGroup();
  if (owner == GroupOwner::render_pass && render_) render_.PopDebugGroup();
  if (owner == GroupOwner::encoder) encoder_.PopDebugGroup();
}

void WebGpuEncoder::begin_compute_pass(std::string_view label) {
  wgpu::ComputePassDescriptor descriptor;
  descriptor.label = label;
  compute_ = encoder_.BeginComputePass(&descriptor);
}

void WebGpuEncoder::set_pipeline(rhi::ComputePipelineId pipeline) { compute_.SetPipeline(device_.pipeline(pipeline)); }

void WebGpuEncoder::dispatch(uint32_t x, uint32_t y, uint32_t z) { compute_.DispatchWorkgroups(x, y, z); }

void WebGpuEncoder::end_compute_pass() {
  compute_.End();
  compute_ = nullptr;
}

void WebGpuEncoder::begin_render_pass(const rhi::RenderPassDesc& desc) {
  std::vector<wgpu::RenderPassColorAttachment> colors;
  for (const rhi::ColorAttachment& c : desc.colors) {
    wgpu::RenderPassColorAttachment attachment;
    attachment.view = device_.view(c.view);
    attachment.loadOp = load_op(c.load);
    attachment.storeOp = wgpu::StoreOp::Store;
    attachment.clearValue = color_of(c.clear);
    colors.push_back(attachment);
  }
  wgpu::RenderPassDepthStencilAttachment depth;
  if (desc.depth.view) depth = depth_attachment(device_.view(desc.depth.view), desc.depth);
  wgpu::RenderPassDescriptor descriptor;
  descriptor.label = std::string_view(desc.label);
  descriptor.colorAttachmentCount = colors.size();
  descriptor.colorAttachments = colors.data();
  descriptor.depthStencilAttachment = desc.depth.view ? &depth : nullptr;
  render_ = encoder_.BeginRenderPass(&descriptor);  // viewport and scissor: the attachments, WebGPU's default
}

void WebGpuEncoder::set_pipeline(rhi::RenderPipelineId pipeline) { render_.SetPipeline(device_.pipeline(pipeline)); }

void WebGpuEncoder::set_vertex_buffer(uint32_t slot, rhi::BufferId buffer, uint64_t offset) {
  render_.SetVertexBuffer(slot, device_.buffer(buffer).buffer, offset);
}

void WebGpuEncoder::set_index_buffer(rhi::BufferId buffer, rhi::IndexFormat format, uint64_t offset) {
  const wgpu::IndexFormat f = format == rhi::IndexFormat::uint16 ? wgpu::IndexFormat::Uint16 : wgpu::IndexFormat::Uint32;
  render_.SetIndexBuffer(device_.buffer(buffer).buffer, f, offset);
}

void WebGpuEncoder::draw(uint32_t vertex_count, uint32_t instance_count, uint32_t first_vertex) {
  render_.Draw(vertex_count, instance_count, first_vertex);
}

void WebGpuEncoder::draw_indexed(uint32_t index_count, uint32_t instance_count, uint32_t first_index, int32_t base_vertex) {
  render_.DrawIndexed(index_count, instance_count, first_index, base_vertex);
}

void WebGpuEncoder::end_render_pass() {
  render_.End();
  render_ = nullptr;
}

void WebGpuEncoder::set_bind_group(uint32_t index, rhi::BindGroupId group) {
  if (compute_) compute_.SetBindGroup(index, device_.bind_group(group));
  if (render_) render_.SetBindGroup(index, device_.bind_group(group));
}

// WebGPU writes time stamps only at the beginning or end of a pass (CommandEncoder::
// WriteTimestamp needs Dawn's allow_unsafe_apis): an empty compute pass carries it.
void WebGpuEncoder::write_timestamp(rhi::QuerySetId queries, uint32_t index) {
  if (in_pass()) throw DeviceError(DeviceError::Kind::unsupported, "WebGPU writes time stamps between passes only");
  wgpu::PassTimestampWrites writes;
  writes.querySet = device_.query_set(queries);
  writes.beginningOfPassWriteIndex = index;
  wgpu::ComputePassDescriptor descriptor;
  descriptor.label = "time stamp";
  descriptor.timestampWrites = &writes;
  encoder_.BeginComputePass(&descriptor).End();
}

void WebGpuEncoder::update_buffer(rhi::BufferId buffer, uint64_t offset, std::span<const std::byte> data) {
  if (data.size() > 65536 || data.size() % 4 || offset % 4) {
    throw DeviceError(DeviceError::Kind::other, "update_buffer takes up to 64 KiB, in whole 4-byte words");
  }
  const wgpu::Buffer staging = device_.make_buffer("update_buffer", data.size(), wgpu::BufferUsage::CopySrc | wgpu::BufferUsage::CopyDst);
  device_.context().queue().WriteBuffer(staging, 0, data.data(), data.size());  // runs before this submission
  encoder_.CopyBufferToBuffer(staging, 0, device_.buffer(buffer).buffer, offset, data.size());
  staging_.push_back(staging);
}

WebGpuEncoder::RowCopy WebGpuEncoder::rows_of(rhi::TextureId id, uint32_t mip_level) const {
  const WebGpuDevice::Texture& t = device_.texture(id);
  RowCopy r;
  r.texture.texture = t.texture;
  r.texture.mipLevel = mip_level;
  r.texture.aspect = copy_aspect(t.desc.format);
  const uint32_t width = std::max(1u, t.desc.size.width >> mip_level), height = std::max(1u, t.desc.size.height >> mip_level);
  const uint32_t depth = t.desc.kind == ResourceKind::texture3d ? std::max(1u, t.desc.size.depth >> mip_level) : array_layers(t.desc.kind);
  r.extent = {width, height, depth};
  r.row_bytes = width * format_info(t.desc.format).bytes_per_texel;
  r.padded_bytes = (r.row_bytes + kCopyRowAlignment - 1) / kCopyRowAlignment * kCopyRowAlignment;
  r.rows = height * depth;
  return r;
}

void WebGpuEncoder::copy_rows(const wgpu::Buffer& from, uint64_t from_offset, uint64_t from_stride, const wgpu::Buffer& to,
                              uint64_t to_offset, uint64_t to_stride, const RowCopy& rows) {
  if (rows.row_bytes % 4 || from_offset % 4 || to_offset % 4) {
    throw DeviceError(DeviceError::Kind::unsupported, "WebGPU copies rows of whole 4-byte words at 4-byte offsets");
  }
  for (uint64_t i = 0; i < rows.rows; ++i) {
    encoder_.CopyBufferToBuffer(from, from_offset + i * from_stride, to, to_offset + i * to_stride, rows.row_bytes);
  }
}

// Where a texture's rows are copied to or from: the caller's buffer when its tightly
// packed rows already meet WebGPU's 256-byte alignment, else a staging buffer of padded
// rows (then copied row by row).
wgpu::TexelCopyBufferInfo WebGpuEncoder::copy_buffer_for(const RowCopy& r, const wgpu::Buffer& buffer, uint64_t offset) {
  wgpu::TexelCopyBufferInfo info;
  info.layout.rowsPerImage = r.extent.height;
  if (r.row_bytes == r.padded_bytes) {
    info.buffer = buffer;
    info.layout.offset = offset;
    info.layout.bytesPerRow = r.row_bytes;
    return info;
  }
  info.buffer = device_.make_buffer("padded rows", uint64_t(r.padded_bytes) * r.rows,
                                    wgpu::BufferUsage::CopySrc | wgpu::BufferUsage::CopyDst);
  info.layout.bytesPerRow = r.padded_bytes;
  staging_.push_back(info.buffer);
  return info;
}

void WebGpuEncoder::copy_texture_to_buffer(rhi::TextureId source, rhi::BufferId destination, uint64_t offset, uint32_t mip_level) {
  const RowCopy r = rows_of(source, mip_level);
  const wgpu::Buffer& out = device_.buffer(destination).buffer;
  const wgpu::TexelCopyBufferInfo info = copy_buffer_for(r, out, offset);
  encoder_.CopyTextureToBuffer(&r.texture, &info, &r.extent);
  if (info.buffer.Get() != out.Get()) copy_rows(info.buffer, 0, r.padded_bytes, out, offset, r.row_bytes, r);
}

void WebGpuEncoder::copy_buffer_to_texture(rhi::BufferId source, uint64_t offset, rhi::TextureId destination) {
  const RowCopy r = rows_of(destination);
  const wgpu::Buffer& in = device_.buffer(source).buffer;
  const wgpu::TexelCopyBufferInfo info = copy_buffer_for(r, in, offset);
  if (info.buffer.Get() != in.Get()) copy_rows(in, offset, r.row_bytes, info.buffer, 0, r.padded_bytes, r);
  encoder_.CopyBufferToTexture(&info, &r.texture, &r.extent);
}

void WebGpuEncoder::copy_texture_to_texture(rhi::TextureId source, rhi::TextureId destination) {
  const RowCopy from = rows_of(source), to = rows_of(destination);
  encoder_.CopyTextureToTexture(&from.texture, &to.texture, &from.extent);
}

void WebGpuEncoder::copy_buffer_to_buffer(rhi::BufferId source, rhi::BufferId destination, uint64_t size,
                                          uint64_t destination_offset) {
  encoder_.CopyBufferToBuffer(device_.buffer(source).buffer, 0, device_.buffer(destination).buffer, destination_offset,
                              (size + 3) / 4 * 4);
}

}  // namespace volgraph::webgpu
