// The sky pass's frame block, shared by its variants' shaders (atmosphere_sky*.comp):
// passes/uniform_mirrors.h GpuSkyFrame, written by passes/atmosphere/sky.cpp.
#ifndef VOLGRAPH_ATMOSPHERE_SKY_FRAME_GLSL
#define VOLGRAPH_ATMOSPHERE_SKY_FRAME_GLSL

#include "atmosphere_sky_march.glsl"
#include "view_rays.glsl"

struct SkyPassFrame {
  ViewRays view;
  vec4 planet_up;   // xyz: the camera's zenith, w: its radius clamped to the top (the sky-view LUT's)
  vec4 toward_sun;  // xyz: toward the sun, w: its zenith cosine at the camera
  vec4 sun;         // rgb: E, w: 1 when there is a sun
  vec4 sun_disk;    // x: angular radius, y: 1 to draw the disk, z: 1 to limb-darken it, w: 1 to draw the ground
  vec4 camera;      // x: the camera's radius as it is (m), y: 1 for the multiple-scattering term
  vec4 sampling;    // min and max samples a ray, the length taking the max (m), where in its step each sample sits
};

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
  const SkySampling sampling = SkySampling(f.sampling.x, f.sampling.y, f.sampling.z, f.sampling.w, f.camera.y > 0.5);
  return SkyViewOptions(sampling, f.sun_disk.y > 0.5, f.sun_disk.z > 0.5, f.sun_disk.w > 0.5, f.sun_disk.x);
}

#endif
