#version 450
#extension GL_GOOGLE_include_directive : require
// height_fog: exponential height fog in closed form along each pixel's ray
// (passes/fog/height_fog.cpp): T = e^(−τ), and per directional light, dimmed by the fog
// between each point and the light, L = σs·p·E·attenuated_length_from(a, x, Δ) (Δ the ray's
// unit-density optical depth, a the sun's optical depth at the camera, a + x the view's and
// the sun's at the ray's end: the sun's is linear in Δ, media.glsl); ambient and emission
// (σs·L_ambient + emission)·(1 − T)/σt.
#include "include/light_transmittance.glsl"
#include "include/media.glsl"
#include "include/phase.glsl"
#include "include/pixel_fog.glsl"

// Σ over directional lights of p_HG(θ)·E·∫ e^(−τ_view − τ_sun) dΔ along the ray (per unit
// σs at base height), `density_length` Δ and `sigma_t` the fog's σt at base height.
vec3 directional_light(PixelRay ray, Fogs fogs, float density_length, vec3 sigma_t, float g) {
  const vec3 end = ray.origin + ray.len * ray.direction;
  vec3 sum = vec3(0.0);
  for (int i = 0; i < frame.f.light_list.counts.x; ++i) {
    const Light light = frame.f.light_list.lights[i];
    if (int(light.position_type.w) != LIGHT_DIRECTIONAL) continue;
    const vec3 to_light = -light.direction_cos_outer.xyz;
    const vec3 sun_at_start = fog_optical_depth_to_light(fogs, light, ray.origin, to_light);
    const vec3 sun_at_end = fog_optical_depth_to_light(fogs, light, end, to_light);
    const vec3 across = sigma_t * density_length + sun_at_end - sun_at_start;
    sum += phase_hg(g, dot(light.direction_cos_outer.xyz, -ray.direction)) * light.power_cos_inner.rgb *
           attenuated_length_from(sun_at_start, across, density_length);
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
  // The height fog alone (the pass leaves the scene's other media out).
  const Fogs fogs = fogs_of(ivec4(0, 0, 1, 0), fog, fog, frame.f.media.height);
  // ∫ρ dt along the ray for unit base density, then σt·that is the optical depth.
  const float density_length = height_fog_optical_depth(vec3(1.0), frame.f.media.height.y, frame.f.media.height.x, ray.origin.y,
                                                        ray.direction.y, ray.len).r;
  const vec3 sigma_t = fog.sigma_s_g.rgb + fog.sigma_a.rgb;
  const vec3 uniform_source = fog.sigma_s_g.rgb * frame.f.ambient.rgb + fog.emission.rgb;
  const vec3 scattered = fog.sigma_s_g.rgb * directional_light(ray, fogs, density_length, sigma_t, fog.sigma_s_g.w) +
                         uniform_source * attenuated_length(sigma_t, density_length);
  store_fog(gl_GlobalInvocationID.xy, scattered, transmittance(sigma_t, density_length));
}
