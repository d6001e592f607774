#version 450
#extension GL_GOOGLE_include_directive : require
// Translucency, a refracting solid's first draw (screen-space refraction, after Sousa 2005,
// GPU Gems 2 ch. 19): in place of "what lies straight behind × transmittance", the colour
// before the pass (refracted_color) where the refracted ray meets the opaque surface,
// × the layer's transmittance (replacing what is there). The ray is bent by Bec's form at
// the entry and leaves parallel to where it came from (the slab approximation,
// slab_exit_offset), then reaches the opaque surface behind as the straight ray would,
// displaced; or, with refraction_shape sphere, leaves the sphere tangent at the entry
// (HDRP's sphere model) bent twice. Depth-aware rejection: a sample that lands on something
// in front of the refractor, or off the screen, falls back to the environment cube toward
// the way out where one is wired, else to the straight sample; a sample that lands on the
// sky takes the cube's sky toward the way out.
#include "include/translucency_shadow_set.glsl"
#include "include/translucency.glsl"
#include "include/surface_point.glsl"

layout(location = 0) out vec4 factor;

vec3 refracted_sample(SurfacePoint p);

void write_layer(SurfaceLayer layer, SurfacePoint point) { factor = vec4(layer.transmittance * refracted_sample(point), 1.0); }

#include "include/translucent_surface.glsl"

// Each channel's own refracted sample where the material disperses (KHR_materials_dispersion:
// one lookup per channel at its IOR), else the one IOR's.
vec3 refracted_sample_at(SurfacePoint p, float ior);
vec3 refracted_sample(SurfacePoint p) {
  if (!dispersive()) return refracted_sample_at(p, object.translucency.z);
  const vec3 iors = channel_iors();
  return vec3(refracted_sample_at(p, iors.r).r, refracted_sample_at(p, iors.g).g, refracted_sample_at(p, iors.b).b);
}

// What lies behind at `uv` (texel `texel`): the texel itself for a smooth interface, else the
// mip chain at level `lod` (trilinear; a refracted_color without a chain stays level 0).
vec3 behind_color(ivec2 texel, vec2 uv, float lod) {
  if (lod <= 0.0) return texelFetch(sampler2D(refracted_color, nearest), texel, 0).rgb;
  return textureLod(sampler2D(refracted_color, trilinear), uv, lod).rgb;
}

// Where the refracted ray leaves the solid and which way: the slab approximation (parallel
// to the view ray, displaced across it: slab_exit_offset) or, with refraction_shape sphere,
// the sphere tangent at the entry (sphere_exit: the way out bent twice).
SphereExit refracted_exit(SurfacePoint p, float ior) {
  if (translucency.refraction.x > 0.5) return sphere_exit(p.to_camera, p.normal, ior, p.inside);
  return SphereExit(slab_exit_offset(p.to_camera, p.normal, ior, p.inside), -p.to_camera);
}

vec3 refracted_sample_at(SurfacePoint p, float ior) {
  const ivec2 size = textureSize(sampler2D(scene_depth, nearest), 0);
  const ivec2 here = ivec2(gl_FragCoord.xy);
  if (translucency.options.z < 0.5) return texelFetch(sampler2D(refracted_color, nearest), here, 0).rgb;
  // The opaque surface behind along the straight ray, then displaced across it.
  const float opaque_depth = view_depth_of(texelFetch(sampler2D(scene_depth, nearest), here, 0).r);
  const float behind = opaque_depth * p.distance / p.view_depth;  // view depth to distance along this ray
  // A rough interface blurs what it refracts: the chain's level of its cone's footprint.
  const float lod = refraction_blur_lod(object.emissive.w, ior, behind - p.distance, behind, translucency.options.w);
  const vec3 straight = behind_color(here, (vec2(here) + 0.5) / vec2(size), lod);
  const SphereExit exit = refracted_exit(p, ior);
  const bool slab = translucency.refraction.x < 0.5;
  if (slab && exit.offset == vec3(0.0)) return straight;  // IOR 1 or head-on: exactly the straight sample
  // What screen space cannot show (off the screen, behind the camera, hidden by something in
  // front of the refractor) and the sky where the ray meets no surface: the environment
  // toward the way out, where a cube is wired; else the straight sample.
  const vec3 missed = has_environment_cube() ? environment_toward(exit.direction, refracted_spread(ior)) : straight;
  // The point the way out reaches at the distance the straight ray meets the opaque surface.
  const vec3 exit_point = p.position + exit.offset;
  const vec3 target = slab ? translucency.camera.xyz - p.to_camera * behind + exit.offset
                           : exit_point + exit.direction * max(behind - p.distance - length(exit.offset), 0.0);
  const vec4 clip = frame.view_projection * vec4(target, 1.0);
  if (clip.w <= 0.0) return missed;
  const vec2 uv = vec2(0.5 + 0.5 * clip.x / clip.w, 0.5 - 0.5 * clip.y / clip.w);  // NDC +y is the image's top
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return missed;
  const ivec2 there = ivec2(uv * vec2(size));
  const float depth_there = texelFetch(sampler2D(scene_depth, nearest), there, 0).r;
  if (depth_there <= gl_FragCoord.z) return missed;
  if (depth_there >= 1.0 && has_environment_cube()) return missed;  // the sky: toward the way out, not where the pixel looks
  return textureLod(sampler2D(refracted_color, trilinear), uv, lod).rgb;
}
