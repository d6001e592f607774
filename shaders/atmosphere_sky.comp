#version 450
#extension GL_GOOGLE_include_directive : require
// sky: where the depth is at the far plane, the sky-view LUT in the pixel's direction
// (include/atmosphere_lut.glsl) times the sun's irradiance, plus the sun's disk through the
// transmittance LUT (include/atmosphere_transmittance_lookup.glsl); elsewhere the scene's
// colour as it is.
#include "include/atmosphere_sky_lookup.glsl"
#include "include/view_rays.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform Frame {
  ViewRays view;
  vec4 planet_up;   // xyz: the camera's zenith, w: its radius
  vec4 toward_sun;  // xyz: toward the sun, w: its zenith cosine at the camera
  vec4 sun;         // rgb: E, w: 1 when there is a sun
  vec4 sun_disk;    // x: angular radius, y: 1 to draw the disk
} frame;
layout(set = 0, binding = 2) uniform texture2D surfaces;
layout(set = 0, binding = 3) uniform texture2D depth;
layout(set = 0, binding = 4) uniform sampler nearest;
layout(set = 0, binding = 5) uniform texture2D transmittance;
layout(set = 0, binding = 6) uniform sampler linear;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2D sky_color;
// The variant's own inputs (passes/atmosphere/sky.cpp variant_inputs).
layout(set = 0, binding = 8) uniform texture2D sky_view;

void main() {
  const ivec2 size = imageSize(sky_color);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;
  const vec4 surface = texelFetch(sampler2D(surfaces, nearest), texel, 0);
  if (texelFetch(sampler2D(depth, nearest), texel, 0).r < 1.0 || frame.sun.w < 0.5) {
    imageStore(sky_color, texel, surface);
    return;
  }
  const vec2 ndc = vec2((float(texel.x) + 0.5) / float(size.x) * 2.0 - 1.0, 1.0 - (float(texel.y) + 0.5) / float(size.y) * 2.0);
  const vec3 direction = normalize(view_ray(frame.view, ndc));
  const SkyFrame sky = SkyFrame(frame.planet_up.xyz, frame.planet_up.w, frame.toward_sun.xyz, frame.toward_sun.w);
  vec3 radiance = sky_view_lookup(atmosphere.a, sky_view, linear, sky, direction) * frame.sun.rgb;
  if (frame.sun_disk.y > 0.5) radiance += sun_disk_radiance(atmosphere.a, transmittance, nearest, sky, direction, frame.sun_disk.x) * frame.sun.rgb;
  imageStore(sky_color, texel, vec4(radiance, 1.0));
}
