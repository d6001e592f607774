#version 450
#extension GL_GOOGLE_include_directive : require
// sky, variant raymarch: where the depth is at the far plane, the per-pixel march of the
// pixel's own ray (include/atmosphere_sky_march.glsl: Hillaire 2020's RenderSkyRayMarching
// path, the transmittance and multiple-scattering LUTs read along it, no sky-view LUT)
// times the sun's irradiance; elsewhere the scene's colour as it is (discarded: the pass draws onto it).
#include "include/atmosphere_sky_frame.glsl"

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform Frame { SkyPassFrame f; } frame;
layout(set = 0, binding = 3) uniform texture2D depth;
layout(set = 0, binding = 4) uniform sampler nearest;
layout(set = 0, binding = 5) uniform texture2D transmittance;
layout(set = 0, binding = 6) uniform sampler linear;
// The variant's own inputs (passes/atmosphere/sky.cpp variant_inputs).
layout(set = 0, binding = 8) uniform texture2D multiscattering;

layout(location = 0) out vec4 sky_color;

void main() {
  const ivec2 size = textureSize(sampler2D(depth, nearest), 0);
  const ivec2 texel = ivec2(gl_FragCoord.xy);
  // Surfaces (and everything without a sun) keep the colour under them.
  if (texelFetch(sampler2D(depth, nearest), texel, 0).r < 1.0 || frame.f.sun.w < 0.5) discard;
  const vec3 direction = sky_pixel_direction(frame.f, texel, size);
  const vec3 radiance = marched_sky_radiance(atmosphere.a, transmittance, nearest, multiscattering, linear, sky_frame(frame.f, false),
                                             direction, sky_view_options(frame.f));
  sky_color = vec4(radiance * frame.f.sun.rgb, 1.0);
}
