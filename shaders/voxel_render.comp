#version 450
#extension GL_GOOGLE_include_directive : require
// voxel_render's compute step (passes/voxels/voxel_render.cpp). Variant dda: per pixel, the
// camera ray against the grid's box (slab method), then Amanatides & Woo 1987's DDA from voxel
// to voxel to the first set one; Lambert by the normal of the face the ray entered it through
// (include/voxel_shading.h), over the scene's colour where it misses or the scene is nearer.
// `hit`: the distance (m) along the ray to the entered face, 0 where nothing is hit. Variant
// faces: the scene's colour and hit 0 everywhere, what voxel_faces.frag draws its quads over.
#include "include/voxel_render_params.h"
#include "include/voxel_grid.h"
#include "include/view_rays.glsl"
#include "include/depth_buffer.glsl"
#include "include/voxel_shading.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform VoxelRenderParamsBlock { VoxelRenderParams params; };
layout(set = 0, binding = 1) uniform VoxelGridBlock { VoxelGrid grid; };
layout(set = 0, binding = 2) uniform texture3D voxels;
layout(set = 0, binding = 3) uniform texture2D scene_depth;
layout(set = 0, binding = 4) uniform texture2D scene_color;
layout(set = 0, binding = 5) uniform sampler nearest;
layout(set = 0, binding = 6, rgba16f) uniform writeonly image2D color;
layout(set = 0, binding = 7, r32f) uniform writeonly image2D hit;

const float kFar = 1e30;

bool solid(ivec3 voxel) { return texelFetch(sampler3D(voxels, nearest), voxel, 0).r > 0.5; }

// The ray o + t·d (grid coordinates, d a unit vector) against the box [0, n]³ (Kay & Kajiya
// 1986): x the entry t, y the exit t, z the axis the entry crosses.
vec3 grid_interval(vec3 o, vec3 d, float n) {
  const vec3 safe = mix(vec3(1e-20), d, greaterThan(abs(d), vec3(1e-20)));
  const vec3 t0 = (vec3(0.0) - o) / safe, t1 = (vec3(n) - o) / safe;
  const vec3 near = min(t0, t1), far = max(t0, t1);
  const float axis = near.x >= near.y && near.x >= near.z ? 0.0 : (near.y >= near.z ? 1.0 : 2.0);
  return vec3(max(max(near.x, near.y), near.z), min(min(far.x, far.y), far.z), axis);
}

// Amanatides & Woo 1987: x the t (grid units) of the entered face of the first set voxel, y
// the axis crossed there (−1: the ray started inside it); x < 0 where the ray meets none.
vec2 traverse(vec3 o, vec3 d) {
  const int n = grid.resolution.x;
  const vec3 span = grid_interval(o, d, float(n));
  const float t_start = max(span.x, 0.0);
  if (span.y < t_start) return vec2(-1.0);
  int axis = span.x > 0.0 ? int(span.z) : -1;
  float t = t_start;
  ivec3 voxel = clamp(ivec3(floor(o + t * d)), ivec3(0), ivec3(n - 1));
  const ivec3 stride = ivec3(sign(d));
  const vec3 inverse = vec3(abs(d.x) > 1e-20 ? 1.0 / d.x : kFar, abs(d.y) > 1e-20 ? 1.0 / d.y : kFar, abs(d.z) > 1e-20 ? 1.0 / d.z : kFar);
  const vec3 boundary = vec3(voxel) + vec3(greaterThan(d, vec3(0.0)));
  vec3 t_max = mix(vec3(kFar), (boundary - o) * inverse, notEqual(stride, ivec3(0)));
  const vec3 t_delta = abs(inverse);
  for (int i = 0; i < 3 * n + 3; ++i) {
    if (solid(voxel)) return vec2(t, float(axis));
    axis = t_max.x <= t_max.y && t_max.x <= t_max.z ? 0 : (t_max.y <= t_max.z ? 1 : 2);
    t = t_max[axis];
    voxel[axis] += stride[axis];
    t_max[axis] += t_delta[axis];
    if (voxel[axis] < 0 || voxel[axis] >= n) break;
  }
  return vec2(-1.0);
}

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy), size = imageSize(color);
  if (any(greaterThanEqual(pixel, size))) return;
  const vec3 ray = view_ray(params.view, grid_ndc(vec2(pixel), vec2(0.0), vec2(size)));
  const vec3 d = normalize(ray);
  const float voxel_side = grid.origin.w;
  const vec3 o = (params.view.position.xyz - grid.origin.xyz) / voxel_side;
  const float surface_z = linear_view_depth(texelFetch(sampler2D(scene_depth, nearest), pixel, 0).r,
                                            params.view.position.w, params.view.forward.w);
  const float surface_distance = surface_z * length(ray);
  const vec2 found = params.variant.x == VOXEL_RENDER_DDA ? traverse(o, d) : vec2(-1.0);
  const float distance = found.x * voxel_side;
  vec3 result = texelFetch(sampler2D(scene_color, nearest), pixel, 0).rgb;
  float hit_distance = 0.0;
  if (found.x >= 0.0 && distance < surface_distance) {
    const int axis = int(found.y);
    vec3 normal = -d;
    if (axis >= 0) {
      normal = vec3(0.0);
      normal[axis] = -sign(d[axis]);
    }
    result = voxel_face_radiance(normal, d, params.light_direction, params.light_irradiance.rgb, params.albedo.rgb);
    hit_distance = distance;
  }
  imageStore(color, pixel, vec4(result, 1.0));
  imageStore(hit, pixel, vec4(hit_distance, 0.0, 0.0, 0.0));
}
