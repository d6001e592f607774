#version 450
#extension GL_GOOGLE_include_directive : require
// sky, variant sky_view_lut: where the depth is at the far plane, the sky-view LUT in the
// pixel's direction (include/atmosphere_lut.glsl) times the sun's irradiance, plus the
// sun's disk through the transmittance LUT and the ground
// (include/atmosphere_sky_lookup.glsl); elsewhere the scene's colour as it is (discarded: the pass draws onto it). A camera
// above the atmosphere, which the LUT cannot hold (it is made at the top), gets the
// per-pixel march instead (include/atmosphere_sky_march.glsl), as Hillaire 2020's
// RenderRayMarchingPS does (the sky-view LUT only while viewHeight < TopRadius).
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

void main() {
  const ivec2 size = textureSize(sampler2D(depth, nearest), 0);
  const ivec2 texel = ivec2(gl_FragCoord.xy);
  // Surfaces (and everything without a sun) keep the colour under them.
  if (texelFetch(sampler2D(depth, nearest), texel, 0).r < 1.0 || frame.f.sun.w < 0.5) discard;
  const vec3 direction = sky_pixel_direction(frame.f, texel, size);
  const SkyViewOptions options = sky_view_options(frame.f);
  vec3 radiance;
  if (frame.f.camera.x > atmosphere_top(atmosphere.a)) {
    radiance = marched_sky_radiance(atmosphere.a, transmittance, nearest, multiscattering, linear, sky_frame(frame.f, false), direction, options);
  } else {
    const SkyFrame sky = sky_frame(frame.f, true);
    radiance = sky_view_lookup(atmosphere.a, sky_view, linear, sky, direction);
    if (options.sun_disk) radiance += sun_disk_radiance(atmosphere.a, transmittance, nearest, sky, direction, options.angular_radius, options.limb_darkening);
    if (options.ground) {
      radiance += seen_ground_radiance(atmosphere.a, transmittance, nearest, multiscattering, linear, sky, direction, options.sampling.multiscattering);
    }
  }
  sky_color = vec4(radiance * frame.f.sun.rgb, 1.0);
}
