// The shadow_map pass's light_view buffer: the std140 mirror of ShadowView
// (shaders/include/shadow_view.glsl), the one member of the shaders' ShadowBlock.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace volgraph::plumbing {

struct ShadowViewBlock {
  float light_view_projection[16];  // world → the shadow map's clip space
  float clip_to_world[16];          // its inverse: NDC (x, y, depth in [0, 1], 1) → world
  float params[4];                  // x depth bias, y PCF radius (texels), w shadowed light index
  int32_t mode[4];                  // x: 1 PCF, 0 one tap
  static constexpr std::array<uint64_t, 4> offsets() {
    return {offsetof(ShadowViewBlock, light_view_projection), offsetof(ShadowViewBlock, clip_to_world),
            offsetof(ShadowViewBlock, params), offsetof(ShadowViewBlock, mode)};
  }
};
static_assert(sizeof(ShadowViewBlock) == 160);

}  // namespace volgraph::plumbing
