#version 450
#extension GL_GOOGLE_include_directive : require
// height_fog: exponential height fog in closed form along each pixel's ray
// (passes/fog/height_fog.cpp): T = e^(−τ), L_scat = (σs·(Σ p·E + L_ambient) + emission)·(1 − T)/σt
// with unshadowed directional lights constant along the ray.
#include "include/media.glsl"
#include "include/phase.glsl"
#include "include/pixel_fog.glsl"

// Σ over directional lights of p_HG(θ)·E toward the camera along `direction`.
vec3 directional_light(vec3 direction, float g) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < frame.f.light_list.counts.x; ++i) {
    const Light light = frame.f.light_list.lights[i];
    if (int(light.position_type.w) != LIGHT_DIRECTIONAL) continue;
    sum += phase_hg(g, dot(light.direction_cos_outer.xyz, -direction)) * light.power_cos_inner.rgb;
  }
  return sum;
}

void main() {
  PixelRay ray;
  if (!pixel_ray(gl_GlobalInvocationID.xy, ray)) return;
  const MediumCoefficients fog = frame.f.media.height_fog;
  if (frame.f.media.counts.z == 0) {
    store_fog(gl_GlobalInvocationID.xy, vec3(0.0), vec3(1.0));
    return;
  }
  // ∫ρ dt along the ray for unit base density, then σt·that is the optical depth.
  const float density_length = height_fog_optical_depth(vec3(1.0), frame.f.media.height.y, frame.f.media.height.x, ray.origin.y,
                                                        ray.direction.y, ray.len).r;
  const vec3 sigma_t = fog.sigma_s_g.rgb + fog.sigma_a.rgb;
  const vec3 source = fog.sigma_s_g.rgb * (directional_light(ray.direction, fog.sigma_s_g.w) + frame.f.ambient.rgb) + fog.emission.rgb;
  store_fog(gl_GlobalInvocationID.xy, source * attenuated_length(sigma_t, density_length), transmittance(sigma_t, density_length));
}
