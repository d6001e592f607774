// fog_apply's lookup: the in-scattered radiance and transmittance a per-pixel fog
// technique (raymarch_fog, analytic_fog, height_fog, depth_fog…) wrote into two images,
// read bilinearly at the pixel's centre, so a half-resolution technique upsamples.
#ifndef VOLGRAPH_FOG_IMAGE_LOOKUP_GLSL
#define VOLGRAPH_FOG_IMAGE_LOOKUP_GLSL

layout(set = 0, binding = 0) uniform texture2D fog_scattering;
layout(set = 0, binding = 1) uniform texture2D fog_transmittance;
layout(set = 0, binding = 2) uniform sampler bilinear;

vec2 fog_uv(vec2 frag_coord, vec2 frame_size) { return frag_coord / frame_size; }

#endif
