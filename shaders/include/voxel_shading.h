// voxel_render's shading of a voxel face, the same for every variant (dda's entered face,
// faces' rasterized quad, marching_cubes' smooth triangles): Lambert by the face's normal (DESIGN.md: ρ/π · E · cos θ), lit
// by the scene's first directional light, else a headlight (toward the viewer) of irradiance π.
//
// ONE TEXT FOR BOTH SIDES: GLSL includes this file, C++ includes it inside a namespace with
// GLM's types (passes/voxels/voxel_shading.h).
#ifndef VOLGRAPH_VOXEL_SHADING_H
#define VOLGRAPH_VOXEL_SHADING_H

#include "voxel_fn.h"

#define VOXEL_PI 3.14159265358979f

// The radiance a face of normal `normal` reflects along the unit ray direction `d` toward the
// viewer. `light_direction`: xyz toward the light (unit), w 1 for the scene's sun, 0 for none
// (the headlight); `light_irradiance`: E per channel; `albedo`: ρ per channel.
VOXEL_FN vec3 voxel_face_radiance(vec3 normal, vec3 d, vec4 light_direction, vec3 light_irradiance, vec3 albedo) {
  const bool lit = light_direction.w > 0.5f;
  const vec3 to_light = lit ? vec3(light_direction) : -d;
  const vec3 irradiance = lit ? light_irradiance : vec3(VOXEL_PI);
  return albedo / VOXEL_PI * irradiance * max(dot(normal, to_light), 0.0f);
}

// The same Lambert by a smooth surface's interpolated normal (marching_cubes: the field's
// gradient interpolated across the triangle, no longer of unit length).
VOXEL_FN vec3 voxel_smooth_radiance(vec3 interpolated_normal, vec3 d, vec4 light_direction, vec3 light_irradiance, vec3 albedo) {
  return voxel_face_radiance(normalize(interpolated_normal), d, light_direction, light_irradiance, albedo);
}

#endif  // VOLGRAPH_VOXEL_SHADING_H
