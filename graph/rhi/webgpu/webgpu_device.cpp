// WebGpuDevice (webgpu_device.h): objects, queue writes, submission and read-back.
#include "graph/rhi/webgpu/webgpu_device.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "graph/rhi/webgpu/encoder.h"
#include "graph/rhi/webgpu/formats.h"
#include "graph/rhi/webgpu/graph_resources.h"

namespace volgraph::webgpu {
namespace {

// Adds `value` to a handle table; its index is the handle.
template <typename T>
uint32_t add_to(std::vector<T>& table, T value) {
  table.push_back(std::move(value));
  return uint32_t(table.size() - 1);
}

// WebGPU sizes buffers and queue writes in whole 4-byte words.
constexpr uint64_t whole_words(uint64_t bytes) { return (bytes + 3) / 4 * 4; }

wgpu::BindGroupLayoutEntry layout_entry(const rhi::LayoutEntry& e) {
  wgpu::BindGroupLayoutEntry out;
  out.binding = e.binding;
  out.visibility = shader_stages(e.visibility);
  switch (e.type) {
    case rhi::BindingType::uniform_buffer: out.buffer.type = wgpu::BufferBindingType::Uniform; break;
    case rhi::BindingType::storage_buffer: out.buffer.type = wgpu::BufferBindingType::Storage; break;
    case rhi::BindingType::read_only_storage_buffer: out.buffer.type = wgpu::BufferBindingType::ReadOnlyStorage; break;
    case rhi::BindingType::sampled_texture:
      out.texture.sampleType = e.filtered ? wgpu::TextureSampleType::Float : wgpu::TextureSampleType::UnfilterableFloat;
      out.texture.viewDimension = view_dimension_of(e.texture_kind, e.cube_faces);
      break;
    case rhi::BindingType::sampler:
      out.sampler.type = e.filtered ? wgpu::SamplerBindingType::Filtering : wgpu::SamplerBindingType::NonFiltering;
      break;
    case rhi::BindingType::storage_texture:
      // Dawn's SPIR-V reader (Tint) makes a read-only storage image (imageLoad only) a
      // texture it loads from: the layout must say so (a level of a mip chain, generate_mips).
      if (e.storage_access == rhi::StorageAccess::read_only) {
        out.texture.sampleType = wgpu::TextureSampleType::UnfilterableFloat;
        out.texture.viewDimension = view_dimension_of(e.texture_kind, e.cube_faces);
        break;
      }
      out.storageTexture.access = to_wgpu(e.storage_access);
      out.storageTexture.format = to_wgpu(e.storage_format);
      out.storageTexture.viewDimension = view_dimension_of(e.texture_kind, e.cube_faces);
      break;
  }
  return out;
}

// A level's extent; a cube's depthOrArrayLayers is its six faces at every level.
wgpu::Extent3D level_extent(const rhi::TextureDesc& d, uint32_t level) {
  const uint32_t depth = d.kind == ResourceKind::texture3d ? d.size.depth : 1;
  return {std::max(1u, d.size.width >> level), std::max(1u, d.size.height >> level),
          d.kind == ResourceKind::texture3d ? std::max(1u, depth >> level) : array_layers(d.kind)};
}

}  // namespace

WebGpuDevice::WebGpuDevice(std::unique_ptr<DawnContext> context) : context_(std::move(context)) {}

std::unique_ptr<WebGpuDevice> WebGpuDevice::create(const DawnOptions& options) {
  return std::make_unique<WebGpuDevice>(DawnContext::create(options));
}

void WebGpuDevice::simulate_out_of_memory(std::string_view what) const {
  if (context_->simulated_fault() != SimulatedFault::out_of_memory) return;
  throw DeviceError(DeviceError::Kind::out_of_memory, "Dawn: creating " + std::string(what) + " (simulated)");
}

wgpu::Buffer WebGpuDevice::make_buffer(std::string_view label, uint64_t size, wgpu::BufferUsage usage) const {
  simulate_out_of_memory(label);
  wgpu::BufferDescriptor descriptor;
  descriptor.label = label;
  descriptor.usage = usage;
  descriptor.size = std::max<uint64_t>(4, whole_words(size));
  context_->begin_allocation();
  wgpu::Buffer buffer = context_->device().CreateBuffer(&descriptor);
  context_->end_allocation("buffer \"" + std::string(label) + "\" (" + std::to_string(descriptor.size) + " bytes)");
  return buffer;
}

wgpu::Texture WebGpuDevice::make_texture(const wgpu::TextureDescriptor& descriptor) const {
  const std::string label(std::string_view(descriptor.label));
  simulate_out_of_memory(label);
  context_->begin_allocation();
  wgpu::Texture texture = context_->device().CreateTexture(&descriptor);
  const wgpu::Extent3D& s = descriptor.size;
  context_->end_allocation("texture \"" + label + "\" (" + std::to_string(s.width) + "x" + std::to_string(s.height) + "x" +
                           std::to_string(s.depthOrArrayLayers) + ", " + std::to_string(descriptor.mipLevelCount) +
                           " mip levels)");
  return texture;
}

// A buffer made only to be copied into (the interface's read-back buffers) is mappable;
// any other can also be a copy source, so that read_buffer can copy it out.
rhi::BufferId WebGpuDevice::create_buffer(const rhi::BufferDesc& desc) {
  const bool readback = desc.usage == rhi::buffer_usage::copy_dst;
  const wgpu::BufferUsage usage = readback ? wgpu::BufferUsage::MapRead | wgpu::BufferUsage::CopyDst
                                           : buffer_usage(desc.usage) | wgpu::BufferUsage::CopyDst | wgpu::BufferUsage::CopySrc;
  return {add_to(buffers_, Buffer{make_buffer(desc.label, desc.size, usage), desc.size, readback})};
}

rhi::TextureId WebGpuDevice::create_texture(const rhi::TextureDesc& desc) {
  wgpu::TextureDescriptor descriptor;
  descriptor.label = std::string_view(desc.label);
  descriptor.usage = texture_usage(desc.usage);
  descriptor.dimension = dimension_of(desc.kind);
  descriptor.size = level_extent(desc, 0);
  descriptor.format = to_wgpu(desc.format);
  descriptor.mipLevelCount = std::max(1u, desc.mip_levels);
  return add_texture(make_texture(descriptor), desc);
}

rhi::TextureViewId WebGpuDevice::create_view(rhi::TextureId texture) {
  const Texture& t = textures_.at(texture.id);
  wgpu::TextureViewDescriptor whole;
  whole.dimension = view_dimension_of(t.desc.kind);
  return add_view(t.texture.CreateView(&whole));
}

rhi::SamplerId WebGpuDevice::create_sampler(const rhi::SamplerDesc& desc) {
  wgpu::SamplerDescriptor descriptor;
  descriptor.label = std::string_view(desc.label);
  descriptor.addressModeU = to_wgpu(desc.address_u);
  descriptor.addressModeV = to_wgpu(desc.address_v);
  descriptor.addressModeW = to_wgpu(desc.address_w);
  descriptor.magFilter = descriptor.minFilter = to_wgpu(desc.filter);
  descriptor.mipmapFilter = mipmap_filter(desc.mip_filter);
  return {add_to(samplers_, context_->device().CreateSampler(&descriptor))};
}

rhi::ShaderModuleId WebGpuDevice::create_shader_module(std::string_view label, std::span<const uint32_t> spirv) {
  if (spirv.empty()) throw DeviceError(DeviceError::Kind::other, "shader module " + std::string(label) + " has no SPIR-V");
  wgpu::ShaderSourceSPIRV source;
  source.codeSize = uint32_t(spirv.size());
  source.code = spirv.data();
  wgpu::ShaderModuleDescriptor descriptor;
  descriptor.nextInChain = &source;
  descriptor.label = label;
  return {add_to(modules_, context_->device().CreateShaderModule(&descriptor))};
}

rhi::BindGroupLayoutId WebGpuDevice::create_bind_group_layout(const rhi::BindGroupLayoutDesc& desc) {
  std::vector<wgpu::BindGroupLayoutEntry> entries;
  for (const rhi::LayoutEntry& e : desc.entries) entries.push_back(layout_entry(e));
  wgpu::BindGroupLayoutDescriptor descriptor;
  descriptor.label = std::string_view(desc.label);
  descriptor.entryCount = entries.size();
  descriptor.entries = entries.data();
  return {add_to(layouts_, context_->device().CreateBindGroupLayout(&descriptor))};
}

rhi::BindGroupId WebGpuDevice::create_bind_group(const rhi::BindGroupDesc& desc) {
  std::vector<wgpu::BindGroupEntry> entries;
  for (const rhi::BindGroupEntry& e : desc.entries) {
    wgpu::BindGroupEntry out;
    out.binding = e.binding;
    if (e.buffer) {
      out.buffer = buffers_.at(e.buffer.id).buffer;
      out.offset = e.offset;
      out.size = e.size ? e.size : wgpu::kWholeSize;
    }
    if (e.view) out.textureView = views_.at(e.view.id);
    if (e.sampler) out.sampler = samplers_.at(e.sampler.id);
    entries.push_back(out);
  }
  wgpu::BindGroupDescriptor descriptor;
  descriptor.label = std::string_view(desc.label);
  descriptor.layout = layouts_.at(desc.layout.id);
  descriptor.entryCount = entries.size();
  descriptor.entries = entries.data();
  return {add_to(groups_, context_->device().CreateBindGroup(&descriptor))};
}

wgpu::PipelineLayout WebGpuDevice::pipeline_layout(std::string_view label, const std::vector<rhi::BindGroupLayoutId>& layouts) const {
  std::vector<wgpu::BindGroupLayout> sets;
  for (const rhi::BindGroupLayoutId l : layouts) sets.push_back(layouts_.at(l.id));
  wgpu::PipelineLayoutDescriptor descriptor;
  descriptor.label = label;
  descriptor.bindGroupLayoutCount = sets.size();
  descriptor.bindGroupLayouts = sets.data();
  return context_->device().CreatePipelineLayout(&descriptor);
}

rhi::ComputePipelineId WebGpuDevice::create_compute_pipeline(const rhi::ComputePipelineDesc& desc) {
  wgpu::ComputePipelineDescriptor descriptor;
  descriptor.label = std::string_view(desc.label);
  descriptor.layout = pipeline_layout(desc.label, desc.layouts);
  descriptor.compute.module = modules_.at(desc.module.id);
  descriptor.compute.entryPoint = std::string_view(desc.entry_point);
  return {add_to(compute_pipelines_, context_->device().CreateComputePipeline(&descriptor))};
}

namespace {

// The vertex buffers' layouts; their attributes live in `attributes` (reserved: stable).
std::vector<wgpu::VertexBufferLayout> vertex_layouts(const std::vector<rhi::VertexBufferLayout>& buffers,
                                                     std::vector<wgpu::VertexAttribute>& attributes) {
  size_t count = 0;
  for (const rhi::VertexBufferLayout& b : buffers) count += b.attributes.size();
  attributes.reserve(count);
  std::vector<wgpu::VertexBufferLayout> layouts;
  for (const rhi::VertexBufferLayout& b : buffers) {
    const size_t first = attributes.size();
    for (const rhi::VertexAttribute& a : b.attributes) attributes.push_back({nullptr, to_wgpu(a.format), a.offset, a.location});
    wgpu::VertexBufferLayout layout;
    layout.stepMode = wgpu::VertexStepMode::Vertex;
    layout.arrayStride = b.stride;
    layout.attributeCount = b.attributes.size();
    layout.attributes = attributes.data() + first;
    layouts.push_back(layout);
  }
  return layouts;
}

wgpu::DepthStencilState depth_state(const rhi::DepthStencilState& d) {
  wgpu::DepthStencilState out;
  out.format = to_wgpu(d.format);
  out.depthWriteEnabled = d.write ? wgpu::OptionalBool::True : wgpu::OptionalBool::False;
  out.depthCompare = to_wgpu(d.compare);
  out.depthBias = int32_t(std::lround(d.bias_constant));
  out.depthBiasSlopeScale = d.bias_slope;
  return out;
}

// src + dst for colour and alpha.
constexpr wgpu::BlendState kAdditive = {{wgpu::BlendOperation::Add, wgpu::BlendFactor::One, wgpu::BlendFactor::One},
                                        {wgpu::BlendOperation::Add, wgpu::BlendFactor::One, wgpu::BlendFactor::One}};
// dst × src for colour and alpha.
constexpr wgpu::BlendState kMultiply = {{wgpu::BlendOperation::Add, wgpu::BlendFactor::Zero, wgpu::BlendFactor::Src},
                                        {wgpu::BlendOperation::Add, wgpu::BlendFactor::Zero, wgpu::BlendFactor::SrcAlpha}};
// src0 + dst × src1 for colour and alpha (the DualSourceBlending feature).
constexpr wgpu::BlendState kSourcePlusDestTimesSource1 = {
    {wgpu::BlendOperation::Add, wgpu::BlendFactor::One, wgpu::BlendFactor::Src1},
    {wgpu::BlendOperation::Add, wgpu::BlendFactor::One, wgpu::BlendFactor::Src1Alpha}};

// src + dst × (1 − src alpha) for colour and alpha: over, premultiplied.
constexpr wgpu::BlendState kPremultipliedOver = {{wgpu::BlendOperation::Add, wgpu::BlendFactor::One, wgpu::BlendFactor::OneMinusSrcAlpha},
                                                 {wgpu::BlendOperation::Add, wgpu::BlendFactor::One, wgpu::BlendFactor::OneMinusSrcAlpha}};
// dst + src × (1 − dst alpha) for colour and alpha: under, premultiplied (front to back).
constexpr wgpu::BlendState kPremultipliedUnder = {{wgpu::BlendOperation::Add, wgpu::BlendFactor::OneMinusDstAlpha, wgpu::BlendFactor::One},
                                                  {wgpu::BlendOperation::Add, wgpu::BlendFactor::OneMinusDstAlpha, wgpu::BlendFactor::One}};

const wgpu::BlendState* blend_state(rhi::BlendMode mode) {
  switch (mode) {
    case rhi::BlendMode::premultiplied_over: return &kPremultipliedOver;
    case rhi::BlendMode::premultiplied_under: return &kPremultipliedUnder;
    case rhi::BlendMode::additive: return &kAdditive;
    case rhi::BlendMode::multiply: return &kMultiply;
    case rhi::BlendMode::source_plus_dest_times_source1: return &kSourcePlusDestTimesSource1;
    case rhi::BlendMode::replace: break;
  }
  return nullptr;
}

}  // namespace

rhi::RenderPipelineId WebGpuDevice::create_render_pipeline(const rhi::RenderPipelineDesc& desc) {
  std::vector<wgpu::VertexAttribute> attributes;
  const std::vector<wgpu::VertexBufferLayout> buffers = vertex_layouts(desc.vertex_buffers, attributes);
  std::vector<wgpu::ColorTargetState> targets;
  for (const rhi::ColorTargetState& c : desc.colors) {
    wgpu::ColorTargetState target;
    target.format = to_wgpu(c.format);
    target.blend = blend_state(c.blend);
    targets.push_back(target);
  }
  wgpu::RenderPipelineDescriptor descriptor;
  descriptor.label = std::string_view(desc.label);
  descriptor.layout = pipeline_layout(desc.label, desc.layouts);
  descriptor.vertex.module = modules_.at(desc.vertex_module.id);
  descriptor.vertex.entryPoint = std::string_view(desc.vertex_entry);
  descriptor.vertex.bufferCount = buffers.size();
  descriptor.vertex.buffers = buffers.data();
  descriptor.primitive.topology = wgpu::PrimitiveTopology::TriangleList;
  descriptor.primitive.frontFace = desc.front_counter_clockwise ? wgpu::FrontFace::CCW : wgpu::FrontFace::CW;
  descriptor.primitive.cullMode = to_wgpu(desc.cull);
  const wgpu::DepthStencilState depth = depth_state(desc.depth);
  if (desc.depth.format != Format::undefined) descriptor.depthStencil = &depth;
  wgpu::FragmentState fragment;
  if (desc.fragment_module) {
    fragment.module = modules_.at(desc.fragment_module.id);
    fragment.entryPoint = std::string_view(desc.fragment_entry);
    fragment.targetCount = targets.size();
    fragment.targets = targets.data();
    descriptor.fragment = &fragment;
  }
  return {add_to(render_pipelines_, context_->device().CreateRenderPipeline(&descriptor))};
}

rhi::QuerySetId WebGpuDevice::create_timestamp_queries(std::string_view label, uint32_t count) {
  wgpu::QuerySetDescriptor descriptor;
  descriptor.label = label;
  descriptor.type = wgpu::QueryType::Timestamp;
  descriptor.count = count;
  return {add_to(query_sets_, context_->device().CreateQuerySet(&descriptor))};
}

// Resolved into a buffer, copied to a mappable one, mapped: WebGPU time stamps are ns.
std::vector<double> WebGpuDevice::read_timestamps(rhi::QuerySetId queries, uint32_t first, uint32_t count) {
  const uint64_t bytes = uint64_t(count) * sizeof(uint64_t);
  const wgpu::Buffer resolved = make_buffer("time stamps", bytes, wgpu::BufferUsage::QueryResolve | wgpu::BufferUsage::CopySrc);
  const wgpu::Buffer readable = make_buffer("time stamps read-back", bytes, wgpu::BufferUsage::MapRead | wgpu::BufferUsage::CopyDst);
  const wgpu::CommandEncoder encoder = context_->device().CreateCommandEncoder();
  encoder.ResolveQuerySet(query_sets_.at(queries.id), first, count, resolved, 0);
  encoder.CopyBufferToBuffer(resolved, 0, readable, 0, bytes);
  const wgpu::CommandBuffer commands = encoder.Finish();
  context_->queue().Submit(1, &commands);
  const std::vector<std::byte> raw = map_and_read(readable, bytes);
  std::vector<double> ns(count);
  for (uint32_t i = 0; i < count; ++i) {
    uint64_t ticks;
    std::memcpy(&ticks, raw.data() + 8 * i, 8);
    ns[i] = double(ticks);
  }
  return ns;
}

void WebGpuDevice::destroy(rhi::BufferId id) {
  Buffer& b = buffers_.at(id.id);
  if (b.buffer) b.buffer.Destroy();
  b = Buffer{};
}

void WebGpuDevice::destroy(rhi::TextureId id) {
  Texture& t = textures_.at(id.id);
  if (t.texture) t.texture.Destroy();
  t = Texture{};
}

void WebGpuDevice::write_buffer(rhi::BufferId id, uint64_t offset, std::span<const std::byte> data) {
  const Buffer& b = buffers_.at(id.id);
  if (offset + data.size() > b.size) throw DeviceError(DeviceError::Kind::other, "write_buffer past the end of the buffer");
  std::vector<std::byte> words(data.begin(), data.end());
  words.resize(whole_words(words.size()));
  context_->queue().WriteBuffer(b.buffer, offset, words.data(), words.size());
}

// Queue writes take rows tightly packed (no 256-byte row alignment, unlike copies).
void WebGpuDevice::write_texture(rhi::TextureId id, std::span<const std::byte> texels, uint32_t mip_level) {
  const Texture& t = textures_.at(id.id);
  if (mip_level >= std::max(1u, t.desc.mip_levels)) {
    throw DeviceError(DeviceError::Kind::other, "write_texture: " + t.desc.label + " has no mip level " + std::to_string(mip_level));
  }
  const wgpu::Extent3D size = level_extent(t.desc, mip_level);
  wgpu::TexelCopyTextureInfo destination;
  destination.texture = t.texture;
  destination.mipLevel = mip_level;
  destination.aspect = wgpu::TextureAspect::All;
  wgpu::TexelCopyBufferLayout layout;
  layout.bytesPerRow = size.width * format_info(t.desc.format).bytes_per_texel;
  layout.rowsPerImage = size.height;
  context_->queue().WriteTexture(&destination, texels.data(), texels.size(), &layout, &size);
}

std::unique_ptr<rhi::GraphResourceSet> WebGpuDevice::create_graph_resources(const Graph& graph) {
  return std::make_unique<WebGpuGraphResources>(*this, graph);
}

std::unique_ptr<rhi::CommandEncoder> WebGpuDevice::create_command_encoder(std::string_view label) {
  return std::make_unique<WebGpuEncoder>(*this, label);
}

void WebGpuDevice::submit(std::unique_ptr<rhi::CommandEncoder> commands) {
  const wgpu::CommandBuffer buffer = static_cast<WebGpuEncoder&>(*commands).finish();
  if (context_->simulated_fault() == SimulatedFault::device_lost) {
    throw DeviceError(DeviceError::Kind::device_lost, "Dawn: queue submission (simulated)");
  }
  context_->queue().Submit(1, &buffer);
  context_->wait_for_queue();
  context_->check();
}

std::vector<std::byte> WebGpuDevice::map_and_read(const wgpu::Buffer& buffer, uint64_t size) const {
  bool mapped = false;
  const uint64_t mapped_size = std::max<uint64_t>(4, whole_words(size));
  context_->wait(buffer.MapAsync(wgpu::MapMode::Read, 0, mapped_size, wgpu::CallbackMode::WaitAnyOnly,
                                 [&mapped](wgpu::MapAsyncStatus status, wgpu::StringView) {
                                   mapped = status == wgpu::MapAsyncStatus::Success;
                                 }),
                 "a buffer mapping");
  context_->check();
  if (!mapped) throw DeviceError(DeviceError::Kind::other, "Dawn: a read-back buffer could not be mapped");
  const auto* begin = static_cast<const std::byte*>(buffer.GetConstMappedRange(0, mapped_size));
  std::vector<std::byte> out(begin, begin + size);
  buffer.Unmap();
  return out;
}

std::vector<std::byte> WebGpuDevice::read_buffer(rhi::BufferId id) {
  const Buffer& b = buffers_.at(id.id);
  context_->wait_for_queue();
  if (b.mappable) return map_and_read(b.buffer, b.size);
  const wgpu::Buffer readable = make_buffer("read-back", b.size, wgpu::BufferUsage::MapRead | wgpu::BufferUsage::CopyDst);
  const wgpu::CommandEncoder encoder = context_->device().CreateCommandEncoder();
  encoder.CopyBufferToBuffer(b.buffer, 0, readable, 0, whole_words(b.size));
  const wgpu::CommandBuffer commands = encoder.Finish();
  context_->queue().Submit(1, &commands);
  return map_and_read(readable, b.size);
}

rhi::BufferId WebGpuDevice::add_buffer(wgpu::Buffer buffer, uint64_t size) {
  return {add_to(buffers_, Buffer{std::move(buffer), size, false})};
}

rhi::TextureId WebGpuDevice::add_texture(wgpu::Texture texture, const rhi::TextureDesc& desc) {
  return {add_to(textures_, Texture{std::move(texture), desc})};
}

rhi::TextureViewId WebGpuDevice::add_view(wgpu::TextureView view) {
  return {add_to(views_, std::move(view))};
}

}  // namespace volgraph::webgpu
