// The caches every Device keeps for its passes: bind groups by content, stock samplers,
// sampled textures by their source, shader modules, layouts and pipelines by content.
#include <cstring>
#include <type_traits>

#include "graph/rhi/rhi.h"

namespace volgraph::rhi {
namespace {

// Appends the bytes of trivially copyable values to a cache key.
class ContentKey {
 public:
  template <typename T>
    requires std::is_trivially_copyable_v<T>
  ContentKey& add(const T& value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
    return *this;
  }
  ContentKey& add(std::string_view text) { return add(text.size()).raw(text.data(), text.size()); }
  template <typename T>
    requires std::is_trivially_copyable_v<T>
  ContentKey& add_all(std::span<const T> values) {
    return add(values.size()).raw(values.data(), values.size_bytes());
  }
  std::string take() { return std::move(bytes_); }

 private:
  ContentKey& raw(const void* data, size_t size) {
    bytes_.append(static_cast<const char*>(data), size);
    return *this;
  }
  std::string bytes_;
};

ContentKey& add_layout_entries(ContentKey& key, const std::vector<LayoutEntry>& entries) {
  key.add(entries.size());
  for (const LayoutEntry& e : entries) {
    key.add(e.binding).add(e.visibility).add(e.type).add(e.texture_kind).add(e.cube_faces).add(e.storage_format).add(e.filtered).add(e.storage_access);
  }
  return key;
}

ContentKey& add_layouts(ContentKey& key, const std::vector<BindGroupLayoutId>& layouts) {
  key.add(layouts.size());
  for (const BindGroupLayoutId l : layouts) key.add(l.id);
  return key;
}

std::string render_pipeline_key(const RenderPipelineDesc& d) {
  ContentKey key;
  key.add(d.vertex_module.id).add(d.vertex_entry).add(d.fragment_module.id).add(d.fragment_entry);
  key.add(d.vertex_buffers.size());
  for (const VertexBufferLayout& b : d.vertex_buffers) {
    key.add(b.stride).add(b.attributes.size());
    for (const VertexAttribute& a : b.attributes) key.add(a.location).add(a.format).add(a.offset);
  }
  key.add(d.colors.size());
  for (const ColorTargetState& c : d.colors) key.add(c.format).add(c.blend);
  key.add(d.depth.format).add(d.depth.write).add(d.depth.compare).add(d.depth.bias_constant).add(d.depth.bias_slope);
  key.add(d.cull).add(d.front_counter_clockwise);
  return add_layouts(key, d.layouts).take();
}

// The cached object under `key`, made by `make` on the first request.
template <typename Id, typename Make>
Id cached(std::map<std::string, Id, std::less<>>& cache, std::string key, const Make& make) {
  const auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  const Id made = make();
  cache.emplace(std::move(key), made);
  return made;
}

}  // namespace

BindGroupId Device::cached_bind_group(const BindGroupDesc& desc) {
  BindGroupKey key{desc.layout, {}};
  for (const BindGroupEntry& e : desc.entries) {
    key.entries.push_back({e.binding, e.buffer.id, e.offset, e.size, e.view.id, e.sampler.id});
  }
  const auto it = bind_groups_.find(key);
  if (it != bind_groups_.end()) return it->second;
  const BindGroupId group = create_bind_group(desc);
  bind_groups_.emplace(std::move(key), group);
  return group;
}

SamplerId Device::stock_sampler(StockSampler which) {
  SamplerId& sampler = stock_samplers_.at(size_t(which));
  if (sampler) return sampler;
  switch (which) {
    case StockSampler::nearest_clamp: sampler = create_sampler({"nearest clamp"}); break;
    case StockSampler::linear_clamp: sampler = create_sampler({"linear clamp", Filter::linear}); break;
    case StockSampler::trilinear_clamp: sampler = create_sampler({"trilinear clamp", Filter::linear, Filter::linear}); break;
    case StockSampler::linear_repeat:
      sampler = create_sampler({"linear repeat", Filter::linear, Filter::nearest, AddressMode::repeat, AddressMode::repeat,
                                AddressMode::repeat});
      break;
    case StockSampler::count: break;
  }
  return sampler;
}

TextureViewId Device::cached_texture_view(const std::string& key, const std::function<TextureViewId()>& make) {
  return cached(texture_views_, key, make);
}

ShaderModuleId Device::cached_shader_module(std::string_view label, std::span<const uint32_t> spirv) {
  return cached(shader_modules_, ContentKey().add_all(spirv).take(), [&] { return create_shader_module(label, spirv); });
}

BindGroupLayoutId Device::cached_bind_group_layout(const BindGroupLayoutDesc& desc) {
  ContentKey key;
  return cached(bind_group_layouts_, add_layout_entries(key, desc.entries).take(), [&] { return create_bind_group_layout(desc); });
}

ComputePipelineId Device::cached_compute_pipeline(const ComputePipelineDesc& desc) {
  ContentKey key;
  key.add(desc.module.id).add(desc.entry_point);
  return cached(compute_pipelines_, add_layouts(key, desc.layouts).take(), [&] { return create_compute_pipeline(desc); });
}

RenderPipelineId Device::cached_render_pipeline(const RenderPipelineDesc& desc) {
  return cached(render_pipelines_, render_pipeline_key(desc), [&] { return create_render_pipeline(desc); });
}

}  // namespace volgraph::rhi
