#version 450
#extension GL_GOOGLE_include_directive : require
// sky, variant raymarch: where the depth is at the far plane, the per-pixel march of the
// pixel's own ray (include/atmosphere_sky_march.glsl: Hillaire 2020's RenderSkyRayMarching
// path, the transmittance and multiple-scattering LUTs read along it, no sky-view LUT)
// times the sun's irradiance; elsewhere the scene's colour as it is.
#include "include/atmosphere_sky_frame.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform Frame { SkyPassFrame f; } frame;
layout(set = 0, binding = 2) uniform texture2D surfaces;
layout(set = 0, binding = 3) uniform texture2D depth;
layout(set = 0, binding = 4) uniform sampler nearest;
layout(set = 0, binding = 5) uniform texture2D transmittance;
layout(set = 0, binding = 6) uniform sampler linear;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2D sky_color;
// The variant's own inputs (passes/atmosphere/sky.cpp variant_inputs).
layout(set = 0, binding = 8) uniform texture2D multiscattering;

void main() {
  const ivec2 size = imageSize(sky_color);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;
  const vec4 surface = texelFetch(sampler2D(surfaces, nearest), texel, 0);
  if (texelFetch(sampler2D(depth, nearest), texel, 0).r < 1.0 || frame.f.sun.w < 0.5) {
    imageStore(sky_color, texel, surface);
    return;
  }
  const vec3 direction = sky_pixel_direction(frame.f, texel, size);
  const vec3 radiance = marched_sky_radiance(atmosphere.a, transmittance, nearest, multiscattering, linear, sky_frame(frame.f, false),
                                             direction, sky_view_options(frame.f));
  imageStore(sky_color, texel, vec4(radiance * frame.f.sun.rgb, 1.0));
}
