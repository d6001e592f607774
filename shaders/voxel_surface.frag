#version 450
#extension GL_GOOGLE_include_directive : require
// voxel_render, variant marching_cubes (passes/voxels/voxel_render.cpp): a fragment of the
// extracted surface, Lambert by the interpolated normal (include/voxel_shading.h), kept where it
// is nearer than the scene by dda's rule (distance along the pixel's ray against the scene's
// depth), its distance to `hit`. The interpolated position at the pixel's centre is where the
// pixel's ray meets the triangle: its distance from the camera is the hit distance.
#include "include/voxel_render_params.h"
#include "include/view_rays.glsl"
#include "include/depth_buffer.glsl"
#include "include/voxel_shading.h"

layout(set = 0, binding = 0) uniform VoxelRenderParamsBlock { VoxelRenderParams params; };
layout(set = 0, binding = 1) uniform texture2D scene_depth;
layout(set = 0, binding = 2) uniform sampler nearest;

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 surface_normal;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 hit;

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy);
  const vec2 size = vec2(textureSize(sampler2D(scene_depth, nearest), 0));
  const vec3 ray = view_ray(params.view, grid_ndc(vec2(pixel), vec2(0.0), size));
  const float surface_z = linear_view_depth(texelFetch(sampler2D(scene_depth, nearest), pixel, 0).r,
                                            params.view.position.w, params.view.forward.w);
  const vec3 d = normalize(ray);
  const float distance = length(world_position - params.view.position.xyz);
  if (distance >= surface_z * length(ray)) discard;
  color = vec4(voxel_smooth_radiance(surface_normal, d, params.light_direction, params.light_irradiance.rgb, params.albedo.rgb), 1.0);
  hit = vec4(distance, 0.0, 0.0, 0.0);
}
