// A fog technique against the CPU reference (reference/): the same config rendered on a
// GPU device through the Executor with every composite forced to `none` (linear, no
// exposure) and by the reference at the same size, compared only where the fog
// technique alone decides the pixel.
//
// Exclusions (what differs between the two for reasons outside the fog technique):
// - surfaces: the GPU's surface lighting sees the local media volumes toward the lights
//   only through an opacity shadow map (the reference always: volumetric shadows on
//   surfaces; the global and height fog both dim in closed form), it uses a shadow map
//   (PCF, bias, texel edges) where the reference casts exact shadow rays, and adds the
//   scene pass's ambient term. So a pixel is compared only when its centre and its eight
//   neighbours' centres see no surface (the background, through the media only): the
//   3×3 rule also drops the rasterised silhouettes next to surfaces.
// The media themselves are the same on both sides: the reference evaluates them through
// the GPU's CPU twin (physics::MediaField: edge fades and noise included).
// Metric: tests/support/image_compare.h over the compared pixels — relative mean
// absolute error Σ|gpu − ref| / Σ|ref|, outliers (a channel off by > 5 % of
// max(|ref|, mean |ref|)), largest absolute error.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/rhi.h"
#include "passes/linear_output.h"
#include "reference/image_render.h"
#include "reference/pixel_masks.h"
#include "tests/support/image_compare.h"

namespace volgraph::accuracy {

struct FogComparison {
  testing::ImageDifference difference;
  size_t compared_pixels = 0;
  size_t pixels = 0;
  std::string describe() const;
};

using volgraph::linear_output;  // passes/linear_output.h
using volgraph::load_linear;

// Loads the config from `text`, named `name`, with linear_output applied.
LoadedConfig load_linear_text(const std::string& name, const std::string& text, const PassRegistry& registry,
                              const Overrides& overrides = {});

// The reference image of the config's scene at its output size.
reference::ReferenceImage render_reference(const LoadedConfig& loaded, unsigned threads = 0);

// The config's first graph output after one frame (frame 0: froxels sampled at their
// centres, no jitter), on `device`.
Texels render_gpu(rhi::Device& device, const LoadedConfig& loaded);

using reference::fog_only_pixels;  // reference/pixel_masks.h
using reference::surface_only_pixels;

// The GPU image against the reference over the pixels marked in `compared`.
FogComparison compare_fog(const Texels& gpu, const reference::ReferenceImage& ref, const std::vector<bool>& compared);

}  // namespace volgraph::accuracy
