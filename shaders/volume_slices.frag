#version 450
#extension GL_GOOGLE_include_directive : require
// volume_visualize, variant slices (RTR4 14.3.1: view-aligned slices blended back to front):
// slice k lies at view depth surface.w − k·surface.z; each pixel where the slice crosses the
// box in front of the scene's surface takes the transfer function's colour and opacity there,
// the opacity corrected for the slices' spacing along the pixel's ray (volume_step_opacity),
// premultiplied; the blend is `over` (src + dst·(1 − α)). As the slices grow dense it is the
// ray march's emission-absorption sum, sampled at the planes instead of along the ray.
#include "include/volume_visualize_params.h"
#include "include/volume_transfer.h"
#include "include/view_rays.glsl"
#include "include/depth_buffer.glsl"

layout(set = 0, binding = 0) uniform VolumeVisualizeParamsBlock { VolumeVisualizeParams params; };
layout(set = 0, binding = 1) uniform texture3D density;
layout(set = 0, binding = 2) uniform sampler density_sampler;
layout(set = 0, binding = 3) uniform texture2D scene_depth;
layout(set = 0, binding = 5) uniform sampler nearest;

#include "include/volume_box.glsl"

layout(location = 0) flat in int slice;
layout(location = 0) out vec4 over;

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy), size = textureSize(sampler2D(scene_depth, nearest), 0);
  const vec3 origin = params.view.position.xyz;
  const vec3 ray = view_ray(params.view, grid_ndc(vec2(pixel), vec2(0.0), vec2(size)));
  const float z = params.surface.w - float(slice) * params.surface.z;
  const float surface_z = linear_view_depth(texelFetch(sampler2D(scene_depth, nearest), pixel, 0).r,
                                            params.view.position.w, params.view.forward.w);
  const vec2 box = box_interval(origin, ray);
  if (z < max(box.x, 0.0) || z >= min(box.y, surface_z)) discard;
  const vec4 sample_rgba = transfer_at(origin + z * ray);
  const float alpha = volume_step_opacity(sample_rgba.a, params.surface.z * length(ray), params.surface.y);
  over = vec4(sample_rgba.rgb * alpha, alpha);
}
