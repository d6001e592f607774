#version 450
#extension GL_GOOGLE_include_directive : require
// froxel_voxelize (Wronski 2014, Hillaire 2015): the scene's media averaged over each
// froxel's depth range along its ray — the froxel's centre ray moved across the froxel by
// this frame's jitter (xy), sub-samples inside faded or noisy volumes moved by its z
// (include/media_average.glsl) — into three volumes (passes/fog/froxel_voxelize.cpp).
#include "include/fog_frame.glsl"
#include "include/media_average.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image3D media_scattering;  // σs rgb (1/m), g
layout(set = 0, binding = 2, rgba16f) uniform writeonly image3D media_absorption;  // σa rgb (1/m)
layout(set = 0, binding = 3, rgba16f) uniform writeonly image3D media_emission;    // radiance per metre

const float FP16_MAX = 65000.0;  // stored values are clamped below rgba16f's largest

void main() {
  const uvec3 id = gl_GlobalInvocationID;
  if (any(greaterThanEqual(id, frame.f.grid.size.xyz))) return;
  const vec3 size = vec3(frame.f.grid.size.xyz);
  // Slice k covers view depths [depth(k/N), depth((k+1)/N)]; the ray's forward component is 1.
  const vec3 ray = view_ray(frame.f.view, grid_ndc(vec2(id.xy), frame.f.jitter.xy, size.xy));
  const float near = froxel_depth(frame.f.grid, float(id.z) / size.z);
  const float far = froxel_depth(frame.f.grid, float(id.z + 1) / size.z);
  const MediaSample s = average_media(frame.f.media, frame.f.view.position.xyz, ray, near, far, frame.f.jitter.z);
  imageStore(media_scattering, ivec3(id), vec4(min(s.sigma_s, vec3(FP16_MAX)), s.g));
  imageStore(media_absorption, ivec3(id), vec4(min(s.sigma_a, vec3(FP16_MAX)), 0.0));
  imageStore(media_emission, ivec3(id), vec4(min(s.emission, vec3(FP16_MAX)), 0.0));
}
