#version 450
#extension GL_GOOGLE_include_directive : require
// depth_fog (eq. 14.12–14.14): transmittance f(z), in-scattering (1 − f)·colour, z the
// distance along the pixel's ray (passes/fog/depth_fog.cpp).
#include "include/depth_fog_codes.h"
#include "include/media.glsl"
#include "include/pixel_fog.glsl"
#include "include/depth_fog_params.h"

layout(set = 0, binding = 5) uniform DepthFogParamsBlock { DepthFogParams params; };

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
