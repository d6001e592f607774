// The scene's participating media at a world-space point: global homogeneous fog,
// exponential height fog and local volumes (box, sphere, ellipsoid) whose density is an
// edge fade times procedural noise (noise.glsl), summed; each medium's σs, σa and
// emission scale by its density; g is the σs-weighted mean of the media's. Packed by
// physics/media_field.cpp (std140); CPU twin: physics/media_field.h.
#ifndef VOLGRAPH_MEDIA_FIELD_GLSL
#define VOLGRAPH_MEDIA_FIELD_GLSL
#include "media.glsl"
#include "noise.glsl"

const int SHAPE_BOX = 1;
const int SHAPE_SPHERE = 2;
const int SHAPE_ELLIPSOID = 3;

#include "media_field.h"  // structs MediumCoefficients, MediumVolume, MediaField; GPU_MAX_MEDIUM_VOLUMES

const int MAX_MEDIUM_VOLUMES = GPU_MAX_MEDIUM_VOLUMES;

struct MediaSample {
  vec3 sigma_s;
  vec3 sigma_a;
  vec3 emission;
  float g;
};

// How far inside the volume's surface the local point is (negative outside), in
// local units; the ellipsoid's is approximate (scaled by its smallest radius).
float inside_distance(MediumVolume v, vec3 local) {
  const int shape = int(v.size_shape.w);
  if (shape == SHAPE_BOX) {
    const vec3 d = 0.5 * v.size_shape.xyz - abs(local);
    return min(d.x, min(d.y, d.z));
  }
  if (shape == SHAPE_SPHERE) return v.size_shape.x - length(local);
  const vec3 radii = max(v.size_shape.xyz, vec3(1e-12));
  return (1.0 - length(local / radii)) * min(radii.x, min(radii.y, radii.z));
}

// Edge fade (0 at the surface, 1 from `fade` inside) times the noise density, in the
// volume's local space.
float volume_density(MediumVolume v, vec3 p) {
  const vec3 local = (v.world_to_local * vec4(p, 1.0)).xyz;
  const float d = inside_distance(v, local);
  if (d < 0.0) return 0.0;
  const float fade = v.fade.x > 0.0 ? clamp(d / v.fade.x, 0.0, 1.0) : 1.0;
  const int octaves = int(v.noise.x);
  if (octaves == 0 || fade == 0.0) return fade;
  return fade * noise_density(local * v.noise.y, octaves, v.noise.z);
}

void add_medium(inout MediaSample s, inout float g_weight, MediumCoefficients m, float density) {
  const vec3 sigma_s = m.sigma_s_g.rgb * density;
  s.sigma_s += sigma_s;
  s.sigma_a += m.sigma_a.rgb * density;
  s.emission += m.emission.rgb * density;
  const float weight = sigma_s.r + sigma_s.g + sigma_s.b;
  s.g += m.sigma_s_g.w * weight;
  g_weight += weight;
}

MediaSample sample_media(MediaField field, vec3 p) {
  MediaSample s = MediaSample(vec3(0.0), vec3(0.0), vec3(0.0), 0.0);
  float g_weight = 0.0;
  if (field.counts.y != 0) add_medium(s, g_weight, field.fog, 1.0);
  if (field.counts.z != 0) {
    const float density = exp(min(-field.height.y * (p.y - field.height.x), MAX_EXPONENT));
    add_medium(s, g_weight, field.height_fog, density);
  }
  for (int i = 0; i < field.counts.x; ++i) {
    const float density = volume_density(field.volumes[i], p);
    if (density > 0.0) add_medium(s, g_weight, field.volumes[i].medium, density);
  }
  s.g = g_weight > 0.0 ? s.g / g_weight : 0.0;
  return s;
}

#endif
