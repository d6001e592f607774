// The translucency passes' fragment body: one translucent surface as a layer (C = radiance
// + transmittance ⊙ C_behind, physics/translucency.h's surface_layer), lit as the opaque
// scene is (surface_irradiance.glsl), seen through the froxel volume's media in front of
// it when one is wired (fogged_layer), then through the air in front of it when an
// aerial-perspective volume is wired (fogged_layer again: the graph applies the air after
// the fog), and handed to `write_layer` with its SurfacePoint, which the including
// shader defines with `light_visibility` before including this file. Fragments behind the
// opaque surface are dropped (the opaque depth is sampled: no depth attachment), and with
// TRANSLUCENT_PEELING defined those behind the layer back_depth holds.
#ifndef VOLGRAPH_TRANSLUCENT_SURFACE_GLSL
#define VOLGRAPH_TRANSLUCENT_SURFACE_GLSL
#include "atmosphere_aerial_lookup.glsl"
#include "depth_buffer.glsl"
#include "froxel_sample.glsl"
#include "translucent_material_textures.glsl"
#include "surface_irradiance.glsl"
#include "translucency.glsl"
#include "surface_point.glsl"

#include "translucency_params.h"
layout(set = 0, binding = 1) uniform TranslucencyBlock { TranslucencyParams translucency; };
layout(set = 0, binding = 2) uniform texture2D scene_depth;  // the opaque surfaces'
layout(set = 0, binding = 3) uniform texture2D back_depth;   // the solid translucent objects' back faces
layout(set = 0, binding = 4) uniform sampler nearest;
layout(set = 0, binding = 5) uniform texture2D refracted_color;  // the colour before the pass (screen-space refraction)
layout(set = 0, binding = 6) uniform texture2D back_distance;    // r32f: back_depth's surface's distance from the camera (m)
layout(set = 0, binding = 7) uniform textureCube environment_cube;  // what the surfaces reflect (a 1-texel stand-in when none is wired)

layout(set = 3, binding = 0) uniform FogBlock { FogFrame f; } fog;
layout(set = 3, binding = 1) uniform texture3D integrated_scattering;
layout(set = 3, binding = 2) uniform texture3D integrated_transmittance;
layout(set = 3, binding = 3) uniform sampler trilinear;
layout(set = 3, binding = 4) uniform AerialBlock { AerialLookup f; } air;
layout(set = 3, binding = 5) uniform texture3D aerial_scattering;
layout(set = 3, binding = 6) uniform texture3D aerial_transmittance;

// The environment's radiance toward `direction` over a lobe `spread` rad wide: the wired
// cube's (sky_cube, scene_probe; through cube_mips, a rough lobe reads the level whose texels
// span it), else the uniform radiance of the block (the background, or the sky's mean).
bool has_environment_cube() { return translucency.refraction.y > 0.5; }
vec3 environment_toward(vec3 direction, float spread) {
  if (!has_environment_cube()) return translucency.environment.rgb;
  const float lod = environment_lod(spread, textureSize(samplerCube(environment_cube, trilinear), 0).x);
  return textureLod(samplerCube(environment_cube, trilinear), direction, lod).rgb;
}
// The lobes' widths of the object's rough interface (GGX α = roughness²): 2α reflected,
// 2α(1 − 1/η) refracted (as refraction_blur_lod turns it).
float reflected_spread() { return 2.0 * object.emissive.w * object.emissive.w; }
float refracted_spread(float ior) { return reflected_spread() * (1.0 - 1.0 / max(ior, 1.0)); }

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 2) in vec2 texture_uv;

float view_depth_of(float depth) { return linear_view_depth(depth, translucency.camera.w, translucency.environment.w); }

// The path inside the object along the view ray, by its volume kind: none (thin-walled),
// the shell crossed at the refracted angle, or (solid) from this fragment to the nearer of
// the solids' nearest back face and the opaque surface (the far plane where neither is
// drawn) — the material's thickness where that back face lies in front of the fragment
// (another solid's, nearer: back_depth holds one back face a pixel). A back face's end is
// its float32 distance (back_distance), not its 32-bit depth: ~1e-3 of the path at 30 m.
float inside_path(float cos_view, float distance_to_fragment, float thickness, float ior) {
  const int kind = int(object.attenuation.w);
  if (kind == kVolumeThinWalled) return 0.0;
  if (kind == kVolumeShell) return shell_path_length(thickness, ior, cos_view);
  const ivec2 px = ivec2(gl_FragCoord.xy);
  const float back = texelFetch(sampler2D(back_depth, nearest), px, 0).r, opaque = texelFetch(sampler2D(scene_depth, nearest), px, 0).r;
  const float end = min(back, opaque);
  if (end <= gl_FragCoord.z) return thickness;
  if (back < opaque) return max(texelFetch(sampler2D(back_distance, nearest), px, 0).r - distance_to_fragment, 0.0);
  const float z = view_depth_of(gl_FragCoord.z);
  return (view_depth_of(end) - z) * distance_to_fragment / z;  // view depth to distance along this ray
}

// The IOR of each colour channel (KHR_materials_dispersion; spread on the CPU by
// physics::dispersed_iors and packed by scene_geometry.cpp): red and blue in alpha_test.zw,
// green the IOR itself; without dispersion all three are the one IOR.
vec3 channel_iors() { return vec3(object.alpha_test.z, object.translucency.z, object.alpha_test.w); }
bool dispersive() { return object.alpha_test.z != object.alpha_test.w; }

// The layer where the interface has index `ior`: Fresnel and the path inside at that IOR.
SurfaceLayer layer_at_ior(LayerInputs l, float ior, float cos_view, float inside) {
  l.reflectance = interface_reflectance(ior, cos_view);
  const bool solid = int(object.attenuation.w) == kVolumeSolid;
  l.path_transmittance = exp(-object.attenuation.rgb * (solid ? solid_path_length(inside, ior, cos_view) : inside));
  return surface_layer(l);
}

void main() {
  // The textures first (implicit derivatives need uniform control flow: before any discard).
  const vec3 albedo = material_albedo(object.albedo.rgb, texture_uv);
  const vec3 emission = material_emission(object.emissive.rgb, texture_uv);
  const int alpha_mode = int(object.alpha_test.x);
  const float texel_coverage = material_coverage(object.translucency.x, texture_uv);
  const float transmission = material_transmission(object.translucency.y, texture_uv);
  const float thickness = material_thickness(object.translucency.w, texture_uv);
  // alphaMode mask: a texel below the cutoff is a hole, the rest fully covered; blend: α.
  if (alpha_mode == kAlphaMask && texel_coverage < object.alpha_test.y) discard;
  const float coverage = alpha_mode == kAlphaBlend ? texel_coverage : 1.0;
  if (gl_FragCoord.z >= texelFetch(sampler2D(scene_depth, nearest), ivec2(gl_FragCoord.xy), 0).r) discard;
#ifdef TRANSLUCENT_PEELING
  // Depth peeling: only what lies in front of the layer peeled before (bound as back_depth).
  if (gl_FragCoord.z >= texelFetch(sampler2D(back_depth, nearest), ivec2(gl_FragCoord.xy), 0).r) discard;
#endif
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;
  const vec3 to_camera = translucency.camera.xyz - world_position;
  const float distance_to_fragment = length(to_camera);
  const float cos_view = clamp(dot(n, to_camera / distance_to_fragment), 0.0, 1.0);
  LayerInputs l;
  l.alpha = coverage;
  l.transmission = transmission;
  l.albedo = albedo;
  l.emissive = emission;
  l.irradiance = surface_irradiance(world_position, n);
  l.environment = environment_toward(reflect(-to_camera / distance_to_fragment, n), reflected_spread());  // the mirrored view ray
  const float inside = inside_path(cos_view, distance_to_fragment, thickness, object.translucency.z);  // along the view ray (refraction's offset needs it)
  SurfaceLayer layer = layer_at_ior(l, object.translucency.z, cos_view, inside);
  if (dispersive()) {
    // Dispersion: red and blue each take their own IOR's layer (Fresnel and path per channel).
    const vec3 iors = channel_iors();
    for (int c = 0; c < 3; c += 2) {
      const float ior = iors[c];
      const SurfaceLayer at_ior = layer_at_ior(l, ior, cos_view, inside_path(cos_view, distance_to_fragment, thickness, ior));
      layer.radiance[c] = at_ior.radiance[c];
      layer.transmittance[c] = at_ior.transmittance[c];
    }
  }
  const float z = view_depth_of(gl_FragCoord.z);
  const vec2 uv = gl_FragCoord.xy / vec2(textureSize(sampler2D(scene_depth, nearest), 0));
  if (translucency.options.x > 0.5) {
    const FogAtPixel media = froxel_fog_at(fog.f, integrated_scattering, integrated_transmittance, trilinear, uv, z);
    layer = fogged_layer(layer, media.in_scatter, media.transmittance);
  }
  if (translucency.options.y > 0.5) {
    const AerialAtPoint a = aerial_perspective_at(air.f, aerial_scattering, aerial_transmittance, trilinear, uv, distance_to_fragment);
    layer = fogged_layer(layer, a.in_scatter, a.transmittance);
  }
  write_layer(layer, SurfacePoint(world_position, to_camera / distance_to_fragment, n, distance_to_fragment, z, inside));
}

#endif
