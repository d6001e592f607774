#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_aerial_perspective: per texel (x, y, k), the camera's ray through the centre of
// column (x, y) of the frame, and the air's in-scattering and transmittance over its first
// (k + ½) slices (include/atmosphere_sky.glsl scattering_along, in the planet's frame
// around the camera: include/atmosphere_sky_lookup.glsl).
#include "include/atmosphere_sky.glsl"
#include "include/atmosphere_sky_lookup.glsl"
#include "include/view_rays.glsl"
#include "include/aerial_perspective_frame.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform AerialPerspectiveFrameBlock { AerialPerspectiveFrame frame; };
layout(set = 0, binding = 2) uniform texture2D transmittance;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4) uniform texture2D multiscattering;
layout(set = 0, binding = 5) uniform sampler linear;
layout(set = 0, binding = 6, rgba16f) uniform writeonly image3D aerial_scattering;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image3D aerial_transmittance;

void main() {
  const ivec3 size = imageSize(aerial_scattering);
  const ivec3 texel = ivec3(gl_GlobalInvocationID.xyz);
  if (any(greaterThanEqual(texel, size))) return;
  const vec2 ndc = vec2((float(texel.x) + 0.5) / float(size.x) * 2.0 - 1.0, 1.0 - (float(texel.y) + 0.5) / float(size.y) * 2.0);
  const vec3 direction = normalize(view_ray(frame.view, ndc));
  const SkyFrame sky = SkyFrame(frame.planet_up.xyz, frame.planet_up.w, frame.toward_sun.xyz, frame.toward_sun.w);
  const float mu = clamp(dot(direction, sky.up), -1.0, 1.0);
  const float nu = clamp(dot(direction, sky.toward_sun), -1.0, 1.0);
  const float len = min((float(texel.z) + 0.5) * frame.volume.x, distance_to_boundary(atmosphere.a, sky.r, mu));
  const SkySampling sampling = SkySampling(frame.sampling.x, frame.sampling.y, frame.sampling.z, frame.sampling.w, true);
  // Without a sun (mu_s = −1) the in-scattering is nothing and the transmittance the air's.
  const ScatteringAlong along =
      scattering_along(atmosphere.a, transmittance, nearest, multiscattering, linear, sky.r, mu, sky.mu_s, nu, len, sampling);
  imageStore(aerial_scattering, texel, vec4(along.radiance, 1.0));
  imageStore(aerial_transmittance, texel, vec4(along.transmittance, 1.0));
}
