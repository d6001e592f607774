#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_aerial_perspective (passes/clouds/cloud_aerial_perspective.cpp): the air between
// the camera and the clouds, taken once at the clouds' depth (Hillaire 2016, Frostbite's
// clouds: aerial perspective at the transmittance-weighted mean depth). The layer's
// radiance L and transmittance T_c become L·T_air + S_air·E·(1 − T_c): the air in front
// of the cloud dims what it sends and replaces, where the cloud is opaque, the air the sky
// behind it held. One lookup: include/atmosphere_aerial_lookup.glsl.
#include "include/atmosphere_aerial_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Lookup { AerialLookup f; } lookup;
layout(set = 0, binding = 1) uniform texture2D clouds;
layout(set = 0, binding = 2) uniform texture2D cloud_distance;
layout(set = 0, binding = 3) uniform texture3D aerial_scattering;
layout(set = 0, binding = 4) uniform texture3D aerial_transmittance;
layout(set = 0, binding = 5) uniform sampler trilinear;
layout(set = 0, binding = 6) uniform sampler nearest;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2D clouds_through_air;

const float HALF_MAX = 65504.0;  // rgba16f's largest value

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy), size = imageSize(clouds_through_air);
  if (any(greaterThanEqual(texel, size))) return;
  const vec4 cloud = texelFetch(sampler2D(clouds, nearest), texel, 0);
  if (cloud.a >= 1.0) {  // no cloud: nothing to see through the air
    imageStore(clouds_through_air, texel, cloud);
    return;
  }
  const float t = texelFetch(sampler2D(cloud_distance, nearest), texel, 0).r;
  const vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  const AerialAtPoint air = aerial_perspective_at(lookup.f, aerial_scattering, aerial_transmittance, trilinear, uv, t);
  const vec3 radiance = cloud.rgb * air.transmittance + air.in_scatter * (1.0 - cloud.a);
  imageStore(clouds_through_air, texel, vec4(min(max(radiance, vec3(0.0)), vec3(HALF_MAX)), cloud.a));
}
