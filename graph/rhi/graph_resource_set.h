// The graph's resources on one device, as a backend makes them for a compiled plan.
// Kept out of rhi.h so that the backend interface does not depend on the graph.
#pragma once

#include <cstdint>

#include "graph/plan.h"
#include "graph/rhi/rhi.h"

namespace volgraph::rhi {

// The graph's resources on a device: first the driver's requirements for compile(),
// then memory as the plan says (Vulkan: placed in the plan's heaps; WebGPU: pooled).
class GraphResourceSet {
 public:
  virtual ~GraphResourceSet() = default;
  virtual RequirementsFn requirements() const = 0;
  virtual void bind(const Plan& plan) = 0;
  virtual TextureId texture(uint32_t resource) const = 0;
  virtual TextureViewId view(uint32_t resource) const = 0;  // none for copy-only textures; every mip level
  // One mip level alone (storage images and attachments take one level); level 0 of a
  // texture without a chain is view().
  virtual TextureViewId level_view(uint32_t resource, uint32_t level) const = 0;
  // One face of a texture_cube (0–5: +x, −x, +y, −y, +z, −z) at level 0 as a 2D view: a
  // render target (colour or depth attachment); none for other kinds.
  virtual TextureViewId face_view(uint32_t resource, uint32_t face) const = 0;
  virtual BufferId buffer(uint32_t resource) const = 0;
  // The two resources trade their objects (a history pair, every frame; graph.h).
  virtual void swap(uint32_t a, uint32_t b) = 0;
};

}  // namespace volgraph::rhi
