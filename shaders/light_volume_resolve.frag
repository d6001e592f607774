#version 450
#extension GL_GOOGLE_include_directive : require
// light_volume, last draw: the accumulated in-scattering (rgba32f: the unshadowed sum plus
// the shadow volume's signed faces) into fog_scattering, kept finite and non-negative
// (float rounding of the signed sum can leave −ε where everything is shadowed), and the
// transmittance to the surface, e^(−σt·t_end) (media.glsl).
#include "include/light_volume.glsl"

layout(set = 0, binding = 0) uniform texture2D sums;
layout(set = 0, binding = 1) uniform texture2D ends;
layout(set = 0, binding = 2) uniform sampler nearest;
layout(set = 0, binding = 3) uniform Frame { FogFrame f; } frame;
layout(location = 0) out vec4 scattering;
layout(location = 1) out vec4 transmittance_out;

const float FP16_MAX = 65000.0;  // what rgba16f holds (the default format)

void main() {
  const ivec2 texel = ivec2(gl_FragCoord.xy);
  const vec3 sum = texelFetch(sampler2D(sums, nearest), texel, 0).rgb;
  const bvec3 not_a_number = notEqual(sum, sum);
  scattering = vec4(clamp(mix(sum, vec3(0.0), not_a_number), vec3(0.0), vec3(FP16_MAX)), 0.0);
  const MediumCoefficients fog = frame.f.media.fog;
  const vec3 sigma_t = frame.f.media.counts.y != 0 ? fog.sigma_s_g.rgb + fog.sigma_a.rgb : vec3(0.0);
  transmittance_out = vec4(clamp(transmittance(sigma_t, texelFetch(sampler2D(ends, nearest), texel, 0).a), vec3(0.0), vec3(1.0)), 0.0);
}
