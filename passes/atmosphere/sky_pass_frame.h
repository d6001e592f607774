// The sky's frame block (gpu::SkyPassFrame) as the sky pass and sky_cube fill it: the
// camera and the sun in the planet's frame, how the sky is drawn (sun disk, ground,
// multiple scattering) and the march's sampling (Hillaire 2020: 100 km rays take the max).
#pragma once

#include "graph/rhi/types.h"
#include "passes/uniform_mirrors.h"

namespace volgraph {

struct Scene;

namespace atmosphere {

struct SkyLook {
  bool sun_disk = true;
  bool limb_darkening = false;
  bool ground = true;
  bool multiscattering = true;  // σs · Ψ_ms in the march and Ψ_ms in the ground's light (only where the LUT is wired)
  double min_samples = 40;
  double max_samples = 40;
  double sample_offset = 0.5;
};

// The frame of a sky seen by the scene's camera through an image of `view_extent` (its
// pixels' rays: sky_pixel_direction; a cube computes its own directions).
gpu::SkyPassFrame sky_pass_frame(const Scene& scene, Extent view_extent, const SkyLook& look);

}  // namespace atmosphere
}  // namespace volgraph
