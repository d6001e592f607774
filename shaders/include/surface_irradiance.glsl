// The irradiance E reaching a surface point, shared by the passes that shade the scene's
// surfaces (scene, translucency): the frame's ambient plus Σ E·cos θ·V·T_fog over the
// lights, T_fog the global and height fog's transmittance toward each light in closed form
// (light_transmittance.glsl, as the CPU reference dims surfaces). The including shader
// defines `float light_visibility(int light, vec3 p)` first (1 when unshadowed).
#ifndef VOLGRAPH_SURFACE_IRRADIANCE_GLSL
#define VOLGRAPH_SURFACE_IRRADIANCE_GLSL
#include "light_transmittance.glsl"
#include "scene_uniforms.glsl"

// E·cos θ from one light at p, normal n, through the fogs.
vec3 fogged_irradiance(Fogs fogs, Light light, vec3 p, vec3 n) {
  vec3 travel;
  const vec3 e = light_arriving(light, p, travel);
  const float cos_theta = max(dot(n, -travel), 0.0);
  if (cos_theta <= 0.0 || all(equal(e, vec3(0.0)))) return vec3(0.0);
  return e * cos_theta * fog_transmittance_to_light(fogs, light, p, -travel);
}

// E at p on a surface of unit normal n (turned toward the viewer).
vec3 surface_irradiance(vec3 p, vec3 n) {
  vec3 e = frame.ambient_irradiance.rgb;
  const Fogs fogs = fogs_of(frame.media.counts, frame.media.fog, frame.media.height_fog, frame.media.height);
  for (int i = 0; i < frame.light_list.counts.x; ++i) {
    e += fogged_irradiance(fogs, frame.light_list.lights[i], p, n) * light_visibility(i, p);
  }
  return e;
}

#endif
