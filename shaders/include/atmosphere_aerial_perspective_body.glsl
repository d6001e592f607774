#ifndef VOLGRAPH_ATMOSPHERE_AERIAL_PERSPECTIVE_BODY_GLSL
#define VOLGRAPH_ATMOSPHERE_AERIAL_PERSPECTIVE_BODY_GLSL
// atmosphere_aerial_perspective (passes/atmosphere/aerial_perspective.cpp; wrapped by
// atmosphere_aerial_perspective.comp, and by atmosphere_aerial_perspective_cloud_shadowed.comp
// with AERIAL_CLOUD_SHADOW: cloud_shadow_map's optical depth dims the sun at each sample,
// include/atmosphere_sky.glsl's sun-visibility hook): per texel (x, y, k), the camera's ray
// through the centre of column (x, y) of the frame, and the air's in-scattering and
// transmittance over its first (k + ½) slices (include/atmosphere_sky.glsl scattering_along,
// in the planet's frame around the camera: include/atmosphere_sky_lookup.glsl).
#ifdef AERIAL_CLOUD_SHADOW
#define ATMOSPHERE_SUN_VISIBILITY
#endif
#include "atmosphere_sky.glsl"
#include "atmosphere_sky_lookup.glsl"
#include "view_rays.glsl"
#include "aerial_perspective_frame.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform AerialPerspectiveFrameBlock { AerialPerspectiveFrame frame; };
layout(set = 0, binding = 2) uniform texture2D transmittance;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4) uniform texture2D multiscattering;
layout(set = 0, binding = 5) uniform sampler linear;
layout(set = 0, binding = 6, rgba16f) uniform writeonly image3D aerial_scattering;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image3D aerial_transmittance;

#ifdef AERIAL_CLOUD_SHADOW
#define CLOUD_SHADOW_SET 1
#include "cloud_shadow_set.glsl"
// The cloud layer's transmittance toward the sun (the atmosphere's sun is the map's: Scene::sun_light).
float atmosphere_sun_visibility(vec3 p) {
  return cloud_shadow_transmittance(cloud_shadow, cloud_shadow_sampler, cloud_shadow_view.view, p);
}
#endif

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
  const SkySampling sampling = SkySampling(frame.sampling.x, frame.sampling.y, frame.sampling.z, frame.sampling.w, true, frame.view.position.xyz, direction);
  // Without a sun (mu_s = −1) the in-scattering is nothing and the transmittance the air's.
  const ScatteringAlong along =
      scattering_along(atmosphere.a, transmittance, nearest, multiscattering, linear, sky.r, mu, sky.mu_s, nu, len, sampling);
  imageStore(aerial_scattering, texel, vec4(along.radiance, 1.0));
  imageStore(aerial_transmittance, texel, vec4(along.transmittance, 1.0));
}

#endif
