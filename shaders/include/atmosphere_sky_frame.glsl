// The sky pass's frame block, shared by its variants' shaders (atmosphere_sky*.comp):
// passes/uniform_mirrors.h GpuSkyFrame, written by passes/atmosphere/sky.cpp.
#ifndef VOLGRAPH_ATMOSPHERE_SKY_FRAME_GLSL
#define VOLGRAPH_ATMOSPHERE_SKY_FRAME_GLSL

#include "atmosphere_sky_march.glsl"
#include "view_rays.glsl"

#include "sky_pass_frame.h"  // struct SkyPassFrame

// The pixel's view direction (DESIGN.md's pixel convention: centres, y down).
vec3 sky_pixel_direction(SkyPassFrame f, ivec2 texel, ivec2 size) {
  const vec2 ndc = vec2((float(texel.x) + 0.5) / float(size.x) * 2.0 - 1.0, 1.0 - (float(texel.y) + 0.5) / float(size.y) * 2.0);
  return normalize(view_ray(f.view, ndc));
}

// The camera in the planet's frame: its radius clamped to the top (for the sky-view LUT) or as it is.
SkyFrame sky_frame(SkyPassFrame f, bool clamped) {
  return SkyFrame(f.planet_up.xyz, clamped ? f.planet_up.w : f.camera.x, f.toward_sun.xyz, f.toward_sun.w);
}

SkyViewOptions sky_view_options(SkyPassFrame f) {
  const SkySampling sampling = SkySampling(f.sampling.x, f.sampling.y, f.sampling.z, f.sampling.w, f.camera.y > 0.5, vec3(0.0), vec3(0.0));
  return SkyViewOptions(sampling, f.sun_disk.y > 0.5, f.sun_disk.z > 0.5, f.sun_disk.w > 0.5, f.sun_disk.x);
}

#endif
