#version 450
#extension GL_GOOGLE_include_directive : require
// analytic_fog: single scattering in homogeneous global fog, unshadowed
// (passes/fog/analytic_fog.cpp): point lights by the airlight integral (Sun et al. 2005),
// spot lights by the same integrand cut where the ray crosses the cones (light_volume's
// I(t), light_volume_integral.glsl), directional lights, ambient and emission in closed form.
#include "include/airlight.glsl"
#include "include/light_volume_integral.glsl"
#include "include/media.glsl"
#include "include/pixel_fog.glsl"

// Per unit σs, the radiance one light scatters toward the camera along the ray.
vec3 light_scattering(Light light, PixelRay ray, vec3 sigma_t, float g) {
  const int type = int(light.position_type.w);
  if (type == LIGHT_DIRECTIONAL) {
    return phase_hg(g, dot(light.direction_cos_outer.xyz, -ray.direction)) * light.power_cos_inner.rgb *
           attenuated_length(sigma_t, ray.len);
  }
  if (type == LIGHT_SPOT) return light.power_cos_inner.rgb * point_scattering_to(light, ray.origin, ray.direction, ray.len, sigma_t, g);
  const AirlightGeometry geometry = airlight_geometry(ray.origin, ray.direction, light.position_type.xyz);
  return light.power_cos_inner.rgb * airlight(geometry, ray.len, sigma_t, g);
}

void main() {
  PixelRay ray;
  if (!pixel_ray(gl_GlobalInvocationID.xy, ray)) return;
  const MediumCoefficients fog = frame.f.media.fog;
  if (frame.f.media.counts.y == 0) {
    store_fog(gl_GlobalInvocationID.xy, vec3(0.0), vec3(1.0));
    return;
  }
  const vec3 sigma_s = fog.sigma_s_g.rgb, sigma_t = sigma_s + fog.sigma_a.rgb;
  const float g = fog.sigma_s_g.w;
  vec3 scattered = (sigma_s * frame.f.ambient.rgb + fog.emission.rgb) * attenuated_length(sigma_t, ray.len);
  for (int i = 0; i < frame.f.light_list.counts.x; ++i) {
    scattered += sigma_s * light_scattering(frame.f.light_list.lights[i], ray, sigma_t, g);
  }
  store_fog(gl_GlobalInvocationID.xy, scattered, transmittance(sigma_t, ray.len));
}
