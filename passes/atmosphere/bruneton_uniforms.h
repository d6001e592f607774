// The table shape the Bruneton passes' uniform blocks hold (gpu::BrunetonTableParams, written
// once for GLSL and C++ in shaders/include/bruneton_table_params.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "shaders/include/bruneton_table_params.h"

namespace volgraph {

// The shape of a scattering table of `width` × `height` × `depth` texels holding `nu`
// slices of mu_s texels in x, mu in y and r in z, as the tables' readers take it.
inline gpu::BrunetonTableParams bruneton_table_shape(uint32_t width, uint32_t height, uint32_t depth, int64_t nu) {
  gpu::BrunetonTableParams shape{};
  shape.size[0] = int32_t(nu);
  shape.size[1] = width / nu > 0 ? int32_t(width / nu) : 1;
  shape.size[2] = int32_t(height);
  shape.size[3] = int32_t(depth);
  return shape;
}

}  // namespace volgraph
