// What shadow_map tells the passes that sample it (its light_view buffer, std140).
#ifndef VOLGRAPH_SHADOW_VIEW_GLSL
#define VOLGRAPH_SHADOW_VIEW_GLSL

struct ShadowView {
  mat4 light_view_projection;  // world → the shadow map's clip space
  mat4 clip_to_world;          // its inverse: NDC (x, y, depth in [0, 1], 1) → world
  vec4 params;                 // x depth bias (normalised depth), y PCF radius (texels), w shadowed light index
  ivec4 mode;                  // x: 1 PCF, 0 one tap
};

#endif
