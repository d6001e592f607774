#version 450
#extension GL_GOOGLE_include_directive : require
// light_volume, second draw: the grid's cells (one texel each, N×N), each the normalised
// light depth from which the shadow map's hard lookup (shadow_lookup.glsl: shadowed where
// ndc.z − bias > the stored depth, up to the map's far plane) calls a point shadowed:
// min(depth + bias, 1) of the shadow-map texel under the cell's centre; 1 (nothing
// shadowed) where the map shadows no light.
#include "include/light_volume.glsl"
#include "include/shadow_view.glsl"

layout(set = 0, binding = 0) uniform texture2D shadow_depth;
layout(set = 0, binding = 1) uniform sampler nearest;
layout(set = 0, binding = 2) uniform ShadowBlock { ShadowView view; } shadow;
layout(set = 0, binding = 3) uniform Params { LightVolumeParams p; } params;
layout(location = 0) out float shadow_starts;

void main() {
  if (shadow.view.params.w < 0.0) {
    shadow_starts = 1.0;
    return;
  }
  const ivec2 map_size = textureSize(sampler2D(shadow_depth, nearest), 0);
  const ivec2 texel = ivec2((floor(gl_FragCoord.xy) + 0.5) * vec2(map_size) / float(params.p.sizes.x));
  const float occluder = texelFetch(sampler2D(shadow_depth, nearest), min(texel, map_size - 1), 0).r;
  shadow_starts = min(occluder + shadow.view.params.x, 1.0);
}
