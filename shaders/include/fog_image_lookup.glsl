// fog_apply's lookup: the in-scattered radiance and transmittance a per-pixel fog
// technique (raymarch_fog, analytic_fog, height_fog, depth_fog…) wrote into two images,
// read bilinearly at the pixel's centre, so a half-resolution technique upsamples.
#ifndef VOLGRAPH_FOG_IMAGE_LOOKUP_GLSL
#define VOLGRAPH_FOG_IMAGE_LOOKUP_GLSL

layout(set = 0, binding = 0) uniform texture2D fog_scattering;
layout(set = 0, binding = 1) uniform texture2D fog_transmittance;
layout(set = 0, binding = 2) uniform sampler bilinear;

vec2 fog_uv(vec2 frag_coord, vec2 frame_size) { return frag_coord / frame_size; }

struct FogImages {
  vec3 scattering;
  vec3 transmittance;
};

// Both images at the pixel. Each of fog_apply's two draws reads both, so their shaders
// use the same bindings and one bind group (made with the first draw's reflected layout)
// matches both pipelines — WebGPU requires the layouts to be equal.
FogImages fog_images(vec2 frag_coord, vec2 frame_size) {
  const vec2 uv = fog_uv(frag_coord, frame_size);
  return FogImages(texture(sampler2D(fog_scattering, bilinear), uv).rgb, texture(sampler2D(fog_transmittance, bilinear), uv).rgb);
}

#endif
