#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates the shared physics includes on a table of inputs, for the test that holds
// them to their CPU twins (tests/gpu/physics_twins_test.cpp).
#include "include/airlight.glsl"
#include "include/light_volume_integral.glsl"
#include "include/media.glsl"
#include "include/phase.glsl"

layout(local_size_x = 64) in;

struct Case {
  vec4 phase;  // g, cos θ, airlight t_c, airlight h
  vec4 media;  // x, σt, dz, falloff
  vec4 fog;    // origin y, direction y, airlight length, airlight σt
};
layout(set = 0, binding = 0) readonly buffer Cases { Case cases[]; };
layout(set = 0, binding = 1) writeonly buffer Results { vec4 results[]; };  // three per case

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= cases.length()) return;
  const Case c = cases[i];
  const float g = c.phase.x, cos_theta = c.phase.y;
  results[3 * i] = vec4(phase_hg(g, cos_theta), phase_schlick(schlick_k(g), cos_theta),
                        phase_dual_hg(g, -0.5 * g, 0.7, cos_theta), phase_rayleigh(cos_theta));
  vec3 radiance = vec3(0.0), transmittance_so_far = vec3(1.0);
  integrate_hillaire(radiance, transmittance_so_far, vec3(1.0), vec3(c.media.y), c.media.z);
  const float depth = height_fog_optical_depth(vec3(c.media.y), c.media.w, 0.0, c.fog.x, c.fog.y, c.media.z).r;
  results[3 * i + 1] = vec4(one_minus_exp_over_x(c.media.x), radiance.r, transmittance_so_far.r, depth);
  const AirlightGeometry air = AirlightGeometry(c.phase.z, c.phase.w);
  const float air_g = clamp(g, -0.9, 0.9);  // near |g| = 1 HG's peak amplifies last-bit differences in cos θ
  // light_volume's I(t): a spot at (0, 3, 0) shining down (cones 25° and 35°), a ray from
  // (−4, origin y, 0) across it (tests/gpu/physics_twins_test.cpp builds the same).
  Light spot;
  spot.position_type = vec4(0.0, 3.0, 0.0, float(LIGHT_SPOT));
  spot.direction_cos_outer = vec4(0.0, -1.0, 0.0, 0.8191520443);
  spot.power_cos_inner = vec4(1.0, 1.0, 1.0, 0.9063077870);
  const vec3 ray = normalize(vec3(1.0, 0.3 * c.fog.y, 0.1));
  const float scattered = light_scattering_to(spot, vec3(-4.0, c.fog.x, 0.0), ray, c.fog.z, vec3(c.fog.w), air_g).r;
  results[3 * i + 2] = vec4(airlight(air, c.fog.z, vec3(c.fog.w), air_g).r, airlight_no_extinction(air, c.fog.z),
                            attenuated_length(vec3(c.media.y), c.media.z).r, scattered);
}
