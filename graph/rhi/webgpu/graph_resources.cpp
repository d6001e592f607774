// WebGpuGraphResources (graph_resources.h): pooled objects with the graph's usages.
#include "graph/rhi/webgpu/graph_resources.h"

#include "graph/rhi/webgpu/formats.h"
#include "graph/rhi/webgpu/webgpu_device.h"

namespace volgraph::webgpu {
namespace {

// Usages through which a texture needs a view (bindings and attachments).
constexpr wgpu::TextureUsage kViewable =
    wgpu::TextureUsage::TextureBinding | wgpu::TextureUsage::StorageBinding | wgpu::TextureUsage::RenderAttachment;

}  // namespace

WebGpuGraphResources::WebGpuGraphResources(WebGpuDevice& device, const Graph& graph)
    : device_(device),
      graph_(graph),
      texture_usage_(graph.resources.size(), wgpu::TextureUsage::None),
      buffer_usage_(graph.resources.size(), wgpu::BufferUsage::None) {
  for (const GraphPass& p : graph.passes) {
    for (const ResourceUse& u : p.uses) {
      texture_usage_[u.resource] |= webgpu::texture_usage(u.usage);
      buffer_usage_[u.resource] |= webgpu::buffer_usage(u.usage);
    }
  }
  for (const ResourceVersion& o : graph.outputs) {  // read back after the frame
    texture_usage_[o.resource] |= wgpu::TextureUsage::CopySrc;
    buffer_usage_[o.resource] |= wgpu::BufferUsage::CopySrc;
  }
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {  // a history pair's objects take both roles
    const uint32_t previous = graph.resources[r].previous;
    if (previous == kNone) continue;
    texture_usage_[r] = texture_usage_[previous] = texture_usage_[r] | texture_usage_[previous];
    buffer_usage_[r] = buffer_usage_[previous] = buffer_usage_[r] | buffer_usage_[previous];
  }
}

void WebGpuGraphResources::swap(uint32_t a, uint32_t b) {
  std::swap(textures_.at(a), textures_.at(b));
  std::swap(views_.at(a), views_.at(b));
  std::swap(level_views_.at(a), level_views_.at(b));
  std::swap(face_views_.at(a), face_views_.at(b));
  std::swap(buffers_.at(a), buffers_.at(b));
}

void WebGpuGraphResources::bind(const Plan& plan) {
  const ResourcePool pool = pool_resources(graph_, plan);
  textures_.assign(graph_.resources.size(), {});
  views_.assign(graph_.resources.size(), {});
  level_views_.assign(graph_.resources.size(), {});
  face_views_.assign(graph_.resources.size(), {});
  buffers_.assign(graph_.resources.size(), {});
  for (uint32_t i = 0; i < pool.objects.size(); ++i) create_object(pool.objects[i], i);
}

// One texture or buffer with every occupant's usage, handed to each occupant.
void WebGpuGraphResources::create_object(const PooledObject& object, uint32_t index) {
  const ResourceDesc& d = object.desc;
  wgpu::TextureUsage texture_usage = wgpu::TextureUsage::None;
  wgpu::BufferUsage buffer_usage = wgpu::BufferUsage::None;
  for (const uint32_t r : object.occupants) {
    texture_usage |= texture_usage_[r];
    buffer_usage |= buffer_usage_[r];
  }
  const std::string label = d.name + " (pooled object " + std::to_string(index) + ")";
  rhi::TextureId texture;
  rhi::TextureViewId view;
  std::vector<rhi::TextureViewId> level_views, face_views;
  rhi::BufferId buffer;
  if (d.kind == ResourceKind::buffer) {
    const wgpu::BufferUsage usage = buffer_usage == wgpu::BufferUsage::None ? wgpu::BufferUsage::CopyDst : buffer_usage;
    buffer = device_.add_buffer(device_.make_buffer(label, d.buffer_bytes, usage), d.buffer_bytes);
  } else {
    rhi::TextureDesc desc{label, d.kind, d.format, d.extent, 0, std::max(1u, d.mip_levels)};
    wgpu::TextureDescriptor descriptor;
    descriptor.label = std::string_view(label);
    descriptor.usage = texture_usage == wgpu::TextureUsage::None ? wgpu::TextureUsage::CopyDst : texture_usage;
    descriptor.dimension = dimension_of(d.kind);
    descriptor.size = {d.extent.width, d.extent.height, d.kind == ResourceKind::texture3d ? d.extent.depth : array_layers(d.kind)};
    descriptor.format = to_wgpu(d.format);
    descriptor.mipLevelCount = std::max(1u, d.mip_levels);
    const wgpu::Texture made = device_.make_texture(descriptor);
    texture = device_.add_texture(made, desc);
    wgpu::TextureViewDescriptor whole;
    whole.dimension = view_dimension_of(d.kind);
    if (texture_usage & kViewable) view = device_.add_view(made.CreateView(&whole));
    // A cube's levels are always views of their own: its faces as a 2D array (storage writes).
    const bool cube = d.kind == ResourceKind::texture_cube;
    for (uint32_t level = 0; (texture_usage & kViewable) && (d.mip_levels > 1 || cube) && level < d.mip_levels; ++level) {
      wgpu::TextureViewDescriptor one;
      one.dimension = view_dimension_of(d.kind, true);
      one.baseMipLevel = level;
      one.mipLevelCount = 1;
      level_views.push_back(device_.add_view(made.CreateView(&one)));
    }
    for (uint32_t face = 0; (texture_usage & kViewable) && cube && face < array_layers(d.kind); ++face) {
      wgpu::TextureViewDescriptor one;
      one.dimension = wgpu::TextureViewDimension::e2D;
      one.mipLevelCount = 1;
      one.baseArrayLayer = face;
      one.arrayLayerCount = 1;
      face_views.push_back(device_.add_view(made.CreateView(&one)));
    }
  }
  (object.persistent ? created_.persistent_objects : created_.transient_objects) += 1;
  if (!object.persistent) created_.transient_bytes += estimate_requirements(d).size;
  for (const uint32_t r : object.occupants) {
    textures_[r] = texture;
    views_[r] = view;
    level_views_[r] = level_views;
    face_views_[r] = face_views;
    buffers_[r] = buffer;
  }
}

}  // namespace volgraph::webgpu
