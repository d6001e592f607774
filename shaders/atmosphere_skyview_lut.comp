#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_skyview_lut: per texel, the view direction it holds around the camera
// (Hillaire 2020's latitude/azimuth mapping, include/atmosphere_lut.glsl) and the light
// scattered toward the camera along it (include/atmosphere_sky.glsl).
#include "include/atmosphere_sky.glsl"
#include "include/skyview_lut_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform SkyViewLutParamsBlock { SkyViewLutParams params; };
layout(set = 0, binding = 2) uniform texture2D transmittance;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4) uniform texture2D multiscattering;
layout(set = 0, binding = 5) uniform sampler linear;
layout(set = 0, binding = 6, rgba16f) uniform writeonly image2D sky_view;

void main() {
  const ivec2 size = imageSize(sky_view);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;
  if (params.camera.z < 0.5) {
    imageStore(sky_view, texel, vec4(0.0, 0.0, 0.0, 1.0));
    return;
  }
  const float r = params.camera.x, mu_s = params.camera.y;
  const vec2 direction = sky_view_lut_direction(atmosphere.a, r, (vec2(texel) + 0.5) / vec2(size), size);
  const float nu = view_sun_cosine(direction.x, direction.y, mu_s);
  const SkySampling sampling = SkySampling(params.sampling.x, params.sampling.y, params.sampling.z, params.placement.x, params.sampling.w > 0.5, vec3(0.0), vec3(0.0));
  const vec3 radiance = sky_scattering(atmosphere.a, transmittance, nearest, multiscattering, linear, r, direction.x, mu_s, nu, sampling);
  imageStore(sky_view, texel, vec4(radiance, 1.0));
}
