// froxel_scatter's body (Wronski 2014, Hillaire 2015): per froxel, the light scattered
// toward the camera per metre, S = σs·(Σ_lights p(θ)·E·V·T_media + L_ambient) + emission, T_media
// the media's transmittance toward the light (a march, light_transmittance.glsl; 1 when off)
// (DESIGN.md units), by in_scattering.glsl (shared with raymarch_fog). The including shader
// defines `float light_visibility(int light, vec3 p)` first (1 when unshadowed; a vec3 when it
// also holds the media's transmittance toward that light, from an opacity shadow map) and
// `bool media_shadow_mapped(int light)` (whether light_visibility holds the media's
// transmittance: no march for that light).
#ifndef VOLGRAPH_FROXEL_SCATTER_BODY_GLSL
#define VOLGRAPH_FROXEL_SCATTER_BODY_GLSL
#include "fog_frame.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture3D media_scattering;
layout(set = 0, binding = 2) uniform texture3D media_emission;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4, rgba16f) uniform writeonly image3D in_scatter;
#include "froxel_scatter_params.h"
layout(set = 0, binding = 5) uniform FroxelScatterParamsBlock { FroxelScatterParams params; };

#include "in_scattering.glsl"  // after `frame`, which it reads

const float FP16_MAX = 65000.0;

void main() {
  const uvec3 id = gl_GlobalInvocationID;
  if (any(greaterThanEqual(id, frame.f.grid.size.xyz))) return;
  const vec4 scattering = texelFetch(sampler3D(media_scattering, nearest), ivec3(id), 0);
  const vec3 emission = texelFetch(sampler3D(media_emission, nearest), ivec3(id), 0).rgb;
  const vec3 p = froxel_position(frame.f, vec3(id), frame.f.jitter.xyz);
  const vec3 to_camera = normalize(frame.f.view.position.xyz - p);
  // Froxels the media leave empty (outside every local volume) skip the light loop with
  // skip_empty: whole workgroups of them cost two texel fetches each.
  const vec3 scattered = in_scattering(MediaSample(scattering.rgb, vec3(0.0), emission, scattering.a), p, to_camera,
                                       PhaseChoice(params.modes.x, params.lobes.x, params.lobes.y),
                                       LightMarch(int(params.volumetric.x), params.volumetric.y, 0.5), params.modes.y != 0);
  imageStore(in_scatter, ivec3(id), vec4(min(scattered, vec3(FP16_MAX)), 0.0));
}

#endif
