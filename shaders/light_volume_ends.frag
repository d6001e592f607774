#version 450
#extension GL_GOOGLE_include_directive : require
// light_volume, third draw: per texel, the camera ray to the scene's surface (the far
// plane where nothing was drawn) and everything the fog gives along it without shadows:
// - ends: rgb the shadowed light's in-scattering to the surface, σs·E·I(t_end) (what a face
//   behind the surface adds), a t_end;
// - the sum the shadow volume's faces are added to: σs·Σ_lights E·I(t_end) + (σs·L_ambient
//   + emission)·(1 − e^(−σt·t_end))/σt (shaders/include/light_volume_integral.glsl, media.glsl).
#include "include/light_volume.glsl"
#include "include/light_volume_integral.glsl"
#include "include/shadow_view.glsl"

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture2D scene_depth;
layout(set = 0, binding = 2) uniform sampler nearest;
layout(set = 0, binding = 3) uniform ShadowBlock { ShadowView view; } shadow;
layout(set = 0, binding = 4) uniform Params { LightVolumeParams p; } params;
layout(location = 0) out vec4 ends;
layout(location = 1) out vec4 unshadowed;

const float SOURCE_MAX = 1e30;  // kept finite (a light on the ray)

void main() {
  const PixelRay ray = texel_ray(frame.f, params.p, gl_FragCoord.xy, scene_depth, nearest);
  const MediumCoefficients fog = frame.f.media.fog;
  const vec3 sigma_s = frame.f.media.counts.y != 0 ? fog.sigma_s_g.rgb : vec3(0.0);
  const vec3 sigma_t = sigma_s + (frame.f.media.counts.y != 0 ? fog.sigma_a.rgb : vec3(0.0));
  const vec3 emission = frame.f.media.counts.y != 0 ? fog.emission.rgb : vec3(0.0);
  const int shadowed = int(shadow.view.params.w);
  vec3 sum = (sigma_s * frame.f.ambient.rgb + emission) * attenuated_length(sigma_t, ray.len);
  vec3 shadowed_part = vec3(0.0);
  for (int i = 0; i < frame.f.light_list.counts.x; ++i) {
    const Light light = frame.f.light_list.lights[i];
    const vec3 scattered = min(sigma_s * light.power_cos_inner.rgb *
                                   light_scattering_to(light, ray.origin, ray.direction, ray.len, sigma_t, fog.sigma_s_g.w),
                               vec3(SOURCE_MAX));
    sum += scattered;
    if (i == shadowed) shadowed_part = scattered;
  }
  ends = vec4(shadowed_part, ray.len);
  unshadowed = vec4(min(sum, vec3(SOURCE_MAX)), 0.0);
}
