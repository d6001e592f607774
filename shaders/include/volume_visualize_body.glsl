// volume_visualize (passes/volume/volume_visualize.cpp): each pixel's ray through the
// volume's world box, clipped by the scene's depth, either marched front to back with the
// transfer function (emission-absorption, RTR4 14.3.1) or searched for the first crossing of
// the iso density (refined by bisection, shaded by Lambert with the gradient's normal); the
// result over the scene's colour. Debug outputs: the isosurface's hit point and normal.
// VOLUME_TRANSFER_TABLE: the march's transfer from the 2D table `transfer_table` (density ×
// gradient magnitude) instead of the 1D knots (volume_box.glsl's transfer_at).
#include "include/volume_visualize_params.h"
#include "include/volume_transfer.h"
#include "include/view_rays.glsl"
#include "include/depth_buffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform VolumeVisualizeParamsBlock { VolumeVisualizeParams params; };
layout(set = 0, binding = 1) uniform texture3D density;
layout(set = 0, binding = 2) uniform sampler density_sampler;
layout(set = 0, binding = 3) uniform texture2D scene_depth;
layout(set = 0, binding = 4) uniform texture2D scene_color;
layout(set = 0, binding = 5) uniform sampler nearest;
layout(set = 0, binding = 6, rgba16f) uniform writeonly image2D color;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D hit;
layout(set = 0, binding = 8, rgba16f) uniform writeonly image2D surface_normal;
#ifdef VOLUME_TRANSFER_TABLE
layout(set = 0, binding = 9) uniform texture2D transfer_table;
#endif

const float kPi = 3.14159265358979;

#include "include/volume_box.glsl"

// Emission-absorption front to back over `steps` equal steps, each sampled at its midpoint,
// each step's opacity corrected for its length (volume_step_opacity): rgb the emitted
// colour that arrives, a the transmittance.
vec4 march(vec3 origin, vec3 ray, vec2 span) {
  const int steps = max(params.march.x, 1);
  const float dz = (span.y - span.x) / float(steps);
  const float step_length = dz * length(ray);
  vec3 emitted = vec3(0.0);
  float transmittance = 1.0;
  for (int i = 0; i < steps; ++i) {
    const vec4 sample_rgba = transfer_at(origin + (span.x + (float(i) + 0.5) * dz) * ray);
    const float alpha = volume_step_opacity(sample_rgba.a, step_length, params.surface.y);
    emitted += transmittance * alpha * sample_rgba.rgb;
    transmittance *= 1.0 - alpha;
  }
  return vec4(emitted, transmittance);
}

// The outward normal at p: minus the density's gradient by central differences one texel
// apart (in world units); toward the camera where the gradient vanishes.
vec3 surface_normal_at(vec3 p, vec3 ray) {
  const vec3 gradient = density_gradient(p);
  const float n = length(gradient);
  return n > 1e-6 ? -gradient / n : -normalize(ray);
}

// The first z in span where the density reaches the iso density, or -1: samples `steps`
// equal steps apart from the span's start, then bisects the step where it is crossed.
float first_crossing(vec3 origin, vec3 ray, vec2 span) {
  const float iso = params.surface.x;
  if (density_at(origin + span.x * ray) >= iso) return span.x;
  const int steps = max(params.march.x, 1);
  const float dz = (span.y - span.x) / float(steps);
  for (int i = 1; i <= steps; ++i) {
    const float z = span.x + float(i) * dz;
    if (density_at(origin + z * ray) < iso) continue;
    float below = z - dz, above = z;
    for (int k = 0; k < params.march.y; ++k) {
      const float mid = 0.5 * (below + above);
      if (density_at(origin + mid * ray) >= iso) above = mid; else below = mid;
    }
    return 0.5 * (below + above);
  }
  return -1.0;
}

// Lambert (DESIGN.md: ρ/π · E · cos θ) of the transfer function's colour at the iso
// density, lit by the scene's sun or, without one, a headlight of irradiance π.
vec3 shade(vec3 normal, vec3 ray) {
  const bool lit = params.light_direction.w > 0.5;
  const vec3 to_light = lit ? params.light_direction.xyz : -normalize(ray);
  const vec3 irradiance = lit ? params.light_irradiance.rgb : vec3(kPi);
  return transfer(params.surface.x).rgb / kPi * irradiance * max(dot(normal, to_light), 0.0);
}

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy), size = imageSize(color);
  if (any(greaterThanEqual(pixel, size))) return;
  const vec3 origin = params.view.position.xyz;
  const vec3 ray = view_ray(params.view, grid_ndc(vec2(pixel), vec2(0.0), vec2(size)));
  const float surface_z = linear_view_depth(texelFetch(sampler2D(scene_depth, nearest), pixel, 0).r,
                                            params.view.position.w, params.view.forward.w);
  const vec2 box = box_interval(origin, ray);
  const vec2 span = vec2(max(box.x, 0.0), min(box.y, surface_z));
  const vec3 behind = texelFetch(sampler2D(scene_color, nearest), pixel, 0).rgb;
  vec4 result = vec4(behind, 1.0);
  vec4 hit_point = vec4(0.0), normal = vec4(0.0);
  if (span.x < span.y && params.march.w < VOLUME_VISUALIZE_SLICES) {  // slices, half_angle: the scene behind, blended over next
    if (params.march.w == VOLUME_VISUALIZE_ISOSURFACE) {
      const float z = first_crossing(origin, ray, span);
      if (z >= 0.0) {
        const vec3 p = origin + z * ray;
        normal = vec4(surface_normal_at(p, ray), 1.0);
        hit_point = vec4(p, 1.0);
        result = vec4(shade(normal.xyz, ray), 1.0);
      }
    } else {
      const vec4 marched = march(origin, ray, span);
      result = vec4(behind * marched.a + marched.rgb, 1.0);
    }
  }
  imageStore(color, pixel, result);
  imageStore(hit, pixel, hit_point);
  imageStore(surface_normal, pixel, normal);
}
