#version 450
#extension GL_GOOGLE_include_directive : require
// depth_fog (eq. 14.12–14.14): transmittance f(z), in-scattering (1 − f)·colour, z the
// distance along the pixel's ray (passes/fog/depth_fog.cpp).
#include "include/depth_fog_codes.h"
#include "include/media.glsl"
#include "include/pixel_fog.glsl"

layout(set = 0, binding = 5) uniform Params {
  vec4 fog;    // x start (m), y end (m), z density (1/m), w variant: DEPTH_FOG_* (include/depth_fog_codes.h)
  vec4 color;  // rgb fog radiance
} params;

float fog_factor(float z) {
  const int variant = int(params.fog.w);
  if (variant == DEPTH_FOG_LINEAR) return depth_fog_linear(z, params.fog.x, params.fog.y);
  if (variant == DEPTH_FOG_EXPONENTIAL_SQUARED) return depth_fog_exponential_squared(z, params.fog.z);
  return depth_fog_exponential(z, params.fog.z);  // DEPTH_FOG_EXPONENTIAL
}

void main() {
  PixelRay ray;
  if (!pixel_ray(gl_GlobalInvocationID.xy, ray)) return;
  const float f = fog_factor(ray.len);
  store_fog(gl_GlobalInvocationID.xy, (1.0 - f) * params.color.rgb, vec3(f));
}
