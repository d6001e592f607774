#include "graph/pooling.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace volgraph {
namespace {

using DescKey = std::tuple<ResourceKind, Format, uint32_t, uint32_t, uint32_t, uint64_t, uint32_t>;

DescKey key_of(const ResourceDesc& d) {
  return {d.kind, d.format, d.extent.width, d.extent.height, d.extent.depth, d.kind == ResourceKind::buffer ? d.buffer_bytes : 0, d.mip_levels};
}

// The transients that are used, by first use (then index: deterministic).
std::vector<uint32_t> transients_by_first_use(const Graph& graph, const Plan& plan) {
  std::vector<uint32_t> transients;
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {
    if (plan.lifetimes[r].first != kNone && !graph.resources[r].desc.persistent) transients.push_back(r);
  }
  std::stable_sort(transients.begin(), transients.end(),
                   [&](uint32_t a, uint32_t b) { return plan.lifetimes[a].first < plan.lifetimes[b].first; });
  return transients;
}

class Pooler {
 public:
  Pooler(const Graph& graph, const Plan& plan) : graph_(graph), plan_(plan) {
    pool_.object_of.assign(graph.resources.size(), kNone);
  }

  // An object whose occupants have all finished before `r` starts, or a new one.
  void place_transient(uint32_t r) {
    const Lifetime& life = plan_.lifetimes[r];
    std::vector<uint32_t>& candidates = by_desc_[key_of(graph_.resources[r].desc)];
    for (uint32_t object : candidates) {
      if (!plan_.options.alias || free_after_[object] >= life.first) continue;
      occupy(object, r);
      return;
    }
    candidates.push_back(add_object(r, false));
  }

  void place_persistent(uint32_t r) { add_object(r, true); }

  ResourcePool finish() { return std::move(pool_); }

 private:
  uint32_t add_object(uint32_t r, bool persistent) {
    PooledObject o;
    o.desc = graph_.resources[r].desc;
    o.bytes = plan_.placements[r].requirements.size;
    o.persistent = persistent;
    (persistent ? pool_.persistent_bytes : pool_.transient_bytes) += o.bytes;
    pool_.transient_objects += persistent ? 0 : 1;
    pool_.objects.push_back(std::move(o));
    free_after_.push_back(0);
    occupy(uint32_t(pool_.objects.size() - 1), r);
    return uint32_t(pool_.objects.size() - 1);
  }

  void occupy(uint32_t object, uint32_t r) {
    pool_.objects[object].occupants.push_back(r);
    pool_.object_of[r] = object;
    free_after_[object] = plan_.lifetimes[r].last;
  }

  const Graph& graph_;
  const Plan& plan_;
  ResourcePool pool_;
  std::vector<uint32_t> free_after_;  // per object: its last occupant's last use
  std::map<DescKey, std::vector<uint32_t>> by_desc_;
};

}  // namespace

bool poolable_together(const ResourceDesc& a, const ResourceDesc& b) { return key_of(a) == key_of(b); }

ResourcePool pool_resources(const Graph& graph, const Plan& plan) {
  Pooler pooler(graph, plan);
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {
    if (plan.lifetimes[r].first != kNone && graph.resources[r].desc.persistent) pooler.place_persistent(r);
  }
  for (uint32_t r : transients_by_first_use(graph, plan)) pooler.place_transient(r);
  return pooler.finish();
}

}  // namespace volgraph
