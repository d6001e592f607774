// Transient resources for a backend without placed memory (WebGPU): instead of bytes
// shared in a heap, whole objects are reused. A texture or buffer made for one resource
// is handed to a later resource of the same description (kind, format, size) once every
// use of the first one has run; the objects' sum is what such a backend allocates.
// Persistent resources keep an object of their own; --no-alias gives every resource one.
#pragma once

#include <cstdint>
#include <vector>

#include "graph/plan.h"

namespace volgraph {

struct PooledObject {
  ResourceDesc desc;                // its first occupant's (the name says which)
  uint64_t bytes = 0;               // that occupant's requirement (the plan's placement)
  std::vector<uint32_t> occupants;  // graph resources, in order of first use; never alive together
  bool persistent = false;
};

struct ResourcePool {
  std::vector<uint32_t> object_of;  // per graph resource: index into objects, kNone when unused
  std::vector<PooledObject> objects;
  uint64_t transient_bytes = 0;     // the transient objects' bytes: the pooled figure
  uint64_t persistent_bytes = 0;
  uint32_t transient_objects = 0;
};

// Same description: one object can serve both.
bool poolable_together(const ResourceDesc& a, const ResourceDesc& b);

ResourcePool pool_resources(const Graph& graph, const Plan& plan);

}  // namespace volgraph
