#version 450
// vignette (passes/post/vignette.cpp): the colour × mix(1, cos⁴θ, strength), θ the angle
// between the pixel's ray (DESIGN.md's pixel convention) and the optical axis.
#extension GL_GOOGLE_include_directive : require
#include "include/vignette_params.h"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform texture2D color;
layout(set = 0, binding = 1) uniform sampler nearest;
layout(set = 0, binding = 2, rgba16f) uniform writeonly image2D vignetted;
layout(set = 0, binding = 3) uniform VignetteBlock { VignetteParams params; };

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy), size = imageSize(vignetted);
  if (any(greaterThanEqual(pixel, size))) return;
  const vec2 ndc = vec2((pixel.x + 0.5) / size.x * 2.0 - 1.0, 1.0 - (pixel.y + 0.5) / size.y * 2.0);
  const vec2 slope = ndc * params.lens.x * vec2(params.lens.y, 1.0);  // the ray's tangent per axis
  const float cos2 = 1.0 / (1.0 + dot(slope, slope));
  const vec4 radiance = texelFetch(sampler2D(color, nearest), pixel, 0);
  imageStore(vignetted, pixel, vec4(radiance.rgb * mix(1.0, cos2 * cos2, params.lens.z), radiance.a));
}
