// The media averaged over a stretch of a ray: froxel_voxelize's value of a froxel, the
// mean of sample_media (media_field.glsl) over origin + t·ray, t ∈ [t0, t1]. The global
// fog is uniform; the height fog's mean is exact (its optical depth in closed form,
// media.glsl, over the length); a volume without edge fade or noise holds the exact
// fraction of [t0, t1] inside its shape (shape_interval.glsl); one with an edge fade or
// noise that fraction times the mean density of MEDIA_SUB_SAMPLES points stratified over
// the part inside, each `jitter` (within ±½) of a stratum from the stratum's centre.
// CPU twin: physics/media_average.h.
#ifndef VOLGRAPH_MEDIA_AVERAGE_GLSL
#define VOLGRAPH_MEDIA_AVERAGE_GLSL
#include "media_field.glsl"
#include "shape_interval.glsl"

const int MEDIA_SUB_SAMPLES = 4;

// The volume's size as a scale of its unit shape: box edges, the sphere's radius, the
// ellipsoid's radii.
vec3 unit_shape_scale(MediumVolume v) {
  return int(v.size_shape.w) == SHAPE_SPHERE ? v.size_shape.xxx : v.size_shape.xyz;
}

// Where origin + t·ray runs inside volume v (NO_INTERVAL for a volume of size 0).
vec2 volume_interval(MediumVolume v, vec3 origin, vec3 ray) {
  const vec3 scale = unit_shape_scale(v);
  if (min(scale.x, min(scale.y, scale.z)) <= 0.0) return NO_INTERVAL;
  const vec3 o = (v.world_to_local * vec4(origin, 1.0)).xyz / scale;
  const vec3 d = mat3(v.world_to_local) * ray / scale;
  return int(v.size_shape.w) == SHAPE_BOX ? unit_box_interval(o, d) : unit_ball_interval(o, d);
}

// At most sample_media's largest density, e^MAX_EXPONENT (the closed form overflows past
// it); a froxel whose depth range rounds to nothing gets the density at t0.
float height_fog_mean_density(MediaField field, vec3 origin, vec3 ray, float t0, float t1) {
  const float len = max(t1 - t0, 1e-30);
  const float depth = height_fog_optical_depth(vec3(1.0), field.height.y, field.height.x, origin.y + t0 * ray.y, ray.y, len).x;
  return min(depth / len, exp(MAX_EXPONENT));
}

// The mean density of volume v over [t0, t1], with `samples` stratified points inside it
// where the volume has an edge fade or noise.
float volume_mean_density_sampled(MediumVolume v, vec3 origin, vec3 ray, float t0, float t1, float jitter, int samples) {
  const vec2 chord = volume_interval(v, origin, ray);
  const float a = max(t0, chord.x), b = min(t1, chord.y);
  if (b <= a) return 0.0;
  const float inside = (b - a) / (t1 - t0);
  if (v.fade.x <= 0.0 && int(v.noise.x) == 0) return inside;
  float sum = 0.0;
  for (int k = 0; k < samples; ++k) {
    sum += volume_density(v, origin + (a + (b - a) * (float(k) + 0.5 + jitter) / float(samples)) * ray);
  }
  return inside * sum / float(samples);
}

float volume_mean_density(MediumVolume v, vec3 origin, vec3 ray, float t0, float t1, float jitter) {
  return volume_mean_density_sampled(v, origin, ray, t0, t1, jitter, MEDIA_SUB_SAMPLES);
}

MediaSample average_media(MediaField field, vec3 origin, vec3 ray, float t0, float t1, float jitter) {
  MediaSample s = MediaSample(vec3(0.0), vec3(0.0), vec3(0.0), 0.0);
  float g_weight = 0.0;
  if (field.counts.y != 0) add_medium(s, g_weight, field.fog, 1.0);
  if (field.counts.z != 0) add_medium(s, g_weight, field.height_fog, height_fog_mean_density(field, origin, ray, t0, t1));
  for (int i = 0; i < field.counts.x; ++i) {
    const float density = volume_mean_density(field.volumes[i], origin, ray, t0, t1, jitter);
    if (density > 0.0) add_medium(s, g_weight, field.volumes[i].medium, density);
  }
  s.g = g_weight > 0.0 ? s.g / g_weight : 0.0;
  return s;
}

#endif
