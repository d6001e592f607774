// The caches every Device keeps for its passes: bind groups by content, stock samplers,
// sampled textures by their source.
#include "graph/rhi/rhi.h"

namespace volgraph::rhi {

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
  const auto found = texture_views_.find(key);
  if (found != texture_views_.end()) return found->second;
  const TextureViewId view = make();
  texture_views_.emplace(key, view);
  return view;
}

}  // namespace volgraph::rhi
