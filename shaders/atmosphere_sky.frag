#version 450
#extension GL_GOOGLE_include_directive : require
// sky, variant sky_view_lut: where the depth is at the far plane, the sky in the pixel's
// direction (include/atmosphere_sky_toward.glsl: the sky-view LUT, the sun's disk, the
// ground; the march for a camera above the atmosphere); elsewhere the scene's colour as it
// is (discarded: the pass draws onto it).
#include "include/atmosphere_sky_frame.glsl"

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform Frame { SkyPassFrame f; } frame;
layout(set = 0, binding = 3) uniform texture2D depth;
layout(set = 0, binding = 4) uniform sampler nearest;
layout(set = 0, binding = 5) uniform texture2D transmittance;
layout(set = 0, binding = 6) uniform sampler linear;
// The variant's own inputs (passes/atmosphere/sky.cpp variant_inputs).
layout(set = 0, binding = 8) uniform texture2D sky_view;
layout(set = 0, binding = 9) uniform texture2D multiscattering;  // the sky-view LUT when not wired (camera.y = 0: not read)

layout(location = 0) out vec4 sky_color;

#include "include/atmosphere_sky_toward.glsl"

void main() {
  const ivec2 size = textureSize(sampler2D(depth, nearest), 0);
  const ivec2 texel = ivec2(gl_FragCoord.xy);
  // Surfaces (and everything without a sun) keep the colour under them.
  if (texelFetch(sampler2D(depth, nearest), texel, 0).r < 1.0 || frame.f.sun.w < 0.5) discard;
  sky_color = vec4(sky_radiance_toward(sky_pixel_direction(frame.f, texel, size)), 1.0);
}
