// The shadow_map pass's light_view buffer (shaders/include/shadow_view.glsl, std140).
#pragma once

#include <cstdint>

namespace volgraph::shading {

struct ShadowViewBlock {
  float light_view_projection[16];  // world → the shadow map's clip space
  float clip_to_world[16];          // its inverse: NDC (x, y, depth in [0, 1], 1) → world
  float params[4];                  // x depth bias, y PCF radius (texels), w shadowed light index
  int32_t mode[4];                  // x: 1 PCF, 0 one tap
};
static_assert(sizeof(ShadowViewBlock) == 160);

}  // namespace volgraph::shading
