#version 450
#extension GL_GOOGLE_include_directive : require
// volume_visualize, variant half_angle, the eye's draw of slice k (Kniss et al. 2003): each pixel
// whose ray crosses the slice's plane inside the box, in front of the scene's surface, takes
// the transfer function's opacity there (corrected for the planes' spacing along its ray) and
// emits, premultiplied, colour × E × T_light / 4π: single scattering of the sun's irradiance E
// toward the eye with an isotropic phase, the transfer colour as albedo, T_light the light
// buffer's transmittance at the point (all slices nearer the light; 1 with occlusion off).
#include "include/volume_visualize_params.h"
#include "include/volume_transfer.h"
#include "include/view_rays.glsl"
#include "include/depth_buffer.glsl"

layout(set = 0, binding = 0) uniform VolumeVisualizeParamsBlock { VolumeVisualizeParams params; };
layout(set = 0, binding = 1) uniform texture3D density;
layout(set = 0, binding = 2) uniform sampler density_sampler;
layout(set = 0, binding = 3) uniform texture2D scene_depth;
layout(set = 0, binding = 4) uniform texture2D light_buffer;
layout(set = 0, binding = 5) uniform sampler nearest;

#include "include/volume_box.glsl"
#include "include/volume_half_angle.glsl"

layout(location = 0) flat in int slice;
layout(location = 0) out vec4 emitted;

const float kIsotropicPhase = 0.07957747154594767;  // 1/4π (DESIGN.md: phase functions normalised over the sphere)

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy), size = textureSize(sampler2D(scene_depth, nearest), 0);
  const vec3 origin = params.view.position.xyz;
  const vec3 ray = view_ray(params.view, grid_ndc(vec2(pixel), vec2(0.0), vec2(size)));
  const float along = dot(ray, params.half_axis.xyz);  // |along| ≥ ~0.7: the half vector is within 45° of ±view
  if (abs(along) < 1e-6) discard;
  const float z = (half_angle_slice_offset(slice) - dot(origin, params.half_axis.xyz)) / along;
  const float surface_z = linear_view_depth(texelFetch(sampler2D(scene_depth, nearest), pixel, 0).r,
                                            params.view.position.w, params.view.forward.w);
  const vec2 box = box_interval(origin, ray);
  if (z < max(box.x, 0.0) || z >= min(box.y, surface_z)) discard;
  const vec3 p = origin + z * ray;
  const vec4 sample_rgba = transfer_at(p);
  const float alpha = volume_step_opacity(sample_rgba.a, params.surface.z * length(ray) / abs(along), params.surface.y);
  const float light = params.half_angle_mode.y > 0.5
                          ? textureLod(sampler2D(light_buffer, density_sampler), light_buffer_coordinates(p), 0.0).r
                          : 1.0;
  emitted = vec4(sample_rgba.rgb * params.light_irradiance.rgb * (light * kIsotropicPhase * alpha), alpha);
}
