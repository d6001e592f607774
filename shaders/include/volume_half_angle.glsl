// volume_visualize's half-angle slices (passes/volume/volume_visualize.cpp; Kniss et al. 2003,
// GPU Gems ch. 39 §39.5.1): the planes s·p = half_axis.w + (k + ½)·Δ, k = 0 nearest the light,
// and the light buffer's orthographic view of the box along the light. The including shader
// declares `params` before this file.
#ifndef VOLGRAPH_VOLUME_HALF_ANGLE_GLSL
#define VOLGRAPH_VOLUME_HALF_ANGLE_GLSL

// Slice k's offset along the slices' axis (m); Δ = surface.z.
float half_angle_slice_offset(int k) { return params.half_axis.w + (float(k) + 0.5) * params.surface.z; }

vec3 volume_box_centre() { return 0.5 * (params.box_min.xyz + params.box_max.xyz); }

// The light buffer's texture coordinates of world point p (its orthographic view along the light).
vec2 light_buffer_coordinates(vec3 p) {
  const vec3 d = p - volume_box_centre();
  return 0.5 + 0.5 * vec2(dot(d, params.light_u.xyz), dot(d, params.light_v.xyz)) / params.light_u.w;
}

// The world point of light-buffer coordinates uv on slice k: the light's ray through uv meets the plane.
vec3 light_buffer_point(vec2 uv, int k) {
  const vec2 a = (uv * 2.0 - 1.0) * params.light_u.w;
  const vec3 q = volume_box_centre() + a.x * params.light_u.xyz + a.y * params.light_v.xyz;
  const vec3 toward_light = params.light_direction.xyz, s = params.half_axis.xyz;
  return q + (half_angle_slice_offset(k) - dot(q, s)) / dot(toward_light, s) * toward_light;
}

#endif
