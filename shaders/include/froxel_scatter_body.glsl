// froxel_scatter's body (Wronski 2014, Hillaire 2015): per froxel, the light scattered
// toward the camera per metre, S = σs·(Σ_lights p(θ)·E·V·T_media + L_ambient) + emission, T_media
// the media's transmittance toward the light (a march, light_transmittance.glsl; 1 when off)
// (DESIGN.md units). The including shader defines `float light_visibility(int light,
// vec3 p)` first (1 when unshadowed; a vec3 when it also holds the media's transmittance
// toward that light, from an opacity shadow map) and `bool media_shadow_mapped(int light)`
// (whether light_visibility holds the media's transmittance: no march for that light).
#ifndef VOLGRAPH_FROXEL_SCATTER_BODY_GLSL
#define VOLGRAPH_FROXEL_SCATTER_BODY_GLSL
#include "fog_frame.glsl"
#include "light_transmittance.glsl"
#include "phase.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 1) uniform texture3D media_scattering;
layout(set = 0, binding = 2) uniform texture3D media_emission;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4, rgba16f) uniform writeonly image3D in_scatter;
layout(set = 0, binding = 5) uniform Params {
  ivec4 modes;  // x phase: 0 isotropic, 1 Rayleigh, 2 HG, 3 Schlick, 4 dual-lobe HG; y: 1 skips froxels without scattering
  vec4 lobes;   // dual-lobe HG: x backward g, y forward weight
  vec4 volumetric;  // volumetric self-shadowing: x steps toward each light (0: off), y distance (m)
} params;

const int PHASE_ISOTROPIC = 0;
const int PHASE_RAYLEIGH = 1;
const int PHASE_HG = 2;
const int PHASE_SCHLICK = 3;
const int PHASE_DUAL_HG = 4;
const float FP16_MAX = 65000.0;

// g is the medium's (clamped where HG's peak would overflow rgba16f).
float phase(float g, float cos_theta) {
  g = clamp(g, -HG_MAX_ABS_G_FOR_FP16, HG_MAX_ABS_G_FOR_FP16);
  switch (params.modes.x) {
    case PHASE_ISOTROPIC: return phase_isotropic();
    case PHASE_RAYLEIGH: return phase_rayleigh(cos_theta);
    case PHASE_SCHLICK: return phase_schlick(schlick_k(g), cos_theta);
    case PHASE_DUAL_HG: return phase_dual_hg(g, params.lobes.x, params.lobes.y, cos_theta);
    default: return phase_hg(g, cos_theta);
  }
}

void main() {
  const uvec3 id = gl_GlobalInvocationID;
  if (any(greaterThanEqual(id, frame.f.grid.size.xyz))) return;
  const vec4 scattering = texelFetch(sampler3D(media_scattering, nearest), ivec3(id), 0);
  const vec3 emission = texelFetch(sampler3D(media_emission, nearest), ivec3(id), 0).rgb;
  vec3 scattered = vec3(0.0);
  // Froxels the media leave empty (outside every local volume) skip the light loop: whole
  // workgroups of them cost one texel fetch each.
  if (params.modes.y == 0 || any(greaterThan(scattering.rgb, vec3(0.0)))) {
    const vec3 p = froxel_position(frame.f, vec3(id), frame.f.jitter.xyz);
    const vec3 to_camera = normalize(frame.f.view.position.xyz - p);
    vec3 light = frame.f.ambient.rgb;
    for (int i = 0; i < frame.f.light_list.counts.x; ++i) {
      vec3 travel;
      const vec3 e = light_arriving(frame.f.light_list.lights[i], p, travel);
      const int steps = media_shadow_mapped(i) ? 0 : int(params.volumetric.x);  // a map's light: in light_visibility
      const vec3 media_shadow = transmittance_to_light(frame.f.media, frame.f.light_list.lights[i], p, -travel, steps,
                                                       params.volumetric.y, 0.5);
      light += phase(scattering.a, dot(travel, to_camera)) * e * light_visibility(i, p) * media_shadow;
    }
    scattered = scattering.rgb * light;
  }
  imageStore(in_scatter, ivec3(id), vec4(min(scattered + emission, vec3(FP16_MAX)), 0.0));
}

#endif
