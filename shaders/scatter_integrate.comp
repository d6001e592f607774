#version 450
#extension GL_GOOGLE_include_directive : require
// scatter_integrate: front to back along each froxel column, the in-scattered radiance
// and the transmittance from the camera to the far edge of every slice, by Wronski's
// step (eq. 14.15) or Hillaire's energy-conserving one (eq. 14.16). Slice k covers view
// depths [depth(k/N), depth((k+1)/N)]; distances are along the column's ray.
#include "include/fog_frame.glsl"
#include "include/integration_codes.h"
#include "include/integrate_params.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture3D in_scatter;
layout(set = 0, binding = 2) uniform texture3D media_scattering;
layout(set = 0, binding = 3) uniform texture3D media_absorption;
layout(set = 0, binding = 4) uniform sampler nearest;
layout(set = 0, binding = 5, rgba16f) uniform writeonly image3D integrated_scattering;
layout(set = 0, binding = 6, rgba16f) uniform writeonly image3D integrated_transmittance;
layout(set = 0, binding = 7) uniform IntegrateParamsBlock { IntegrateParams params; };

void main() {
  const uvec3 size = frame.f.grid.size.xyz;
  const uvec2 column = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(column, size.xy))) return;
  const float ray_length = length(view_ray(frame.f.view, grid_ndc(vec2(column), vec2(0.0), vec2(size.xy))));
  vec3 radiance = vec3(0.0), transmittance_so_far = vec3(1.0);
  float near = froxel_depth(frame.f.grid, 0.0);
  for (uint k = 0; k < size.z; ++k) {
    const ivec3 texel = ivec3(column, k);
    const float far = froxel_depth(frame.f.grid, float(k + 1) / float(size.z));
    const float dz = (far - near) * ray_length;
    const vec3 s = texelFetch(sampler3D(in_scatter, nearest), texel, 0).rgb;
    const vec3 sigma_t = texelFetch(sampler3D(media_scattering, nearest), texel, 0).rgb +
                         texelFetch(sampler3D(media_absorption, nearest), texel, 0).rgb;
    if (params.method.x == INTEGRATE_WRONSKI) integrate_wronski(radiance, transmittance_so_far, s, sigma_t, dz);
    else integrate_hillaire(radiance, transmittance_so_far, s, sigma_t, dz);
    imageStore(integrated_scattering, texel, vec4(min(radiance, vec3(65000.0)), 0.0));
    imageStore(integrated_transmittance, texel, vec4(transmittance_so_far, 0.0));
    near = far;
  }
}
