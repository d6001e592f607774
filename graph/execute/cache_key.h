// A pass's cache key: what its outputs depend on. Two frames with equal keys compute
// the same outputs, so a pass declared `cached` (PassDecl::cached) skips the second.
#pragma once

#include <cstdint>
#include <vector>

#include "graph/graph.h"

namespace volgraph {

struct CacheKeyInputs {
  const GraphPass* pass = nullptr;
  uint64_t frame = 0;                // in the key unless the pass is frame_invariant
  uint64_t scene_hash = 0;           // Scene::hash of the parts the pass reads
  std::vector<uint64_t> input_keys;  // the keys of what it reads (its producers' keys)
};

// Its type, variant and parameter values, the scene hash, the inputs' keys and, for a
// pass that is not frame_invariant, the frame number.
uint64_t pass_cache_key(const CacheKeyInputs& in);

}  // namespace volgraph
