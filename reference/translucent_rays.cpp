// The reference renderer's translucent surfaces (reference/renderer.h): layers along the
// camera ray (straight mode), interfaces bent by Snell's law (refracted mode), and the
// translucent surfaces' transmittance on shadow rays.
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/camera.h"
#include "reference/atmosphere_reference.h"
#include "reference/clouds.h"
#include "reference/renderer.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::dot;
using physics::scaled;
using physics::sub;
using physics::times;
using physics::largest;
using physics::is_zero;

constexpr double kSecondaryRayOffset = 1e-9;  // metres per metre of |point|∞, plus 1e-9 m (as shadow rays)


// The next parameter to search from after a hit at t: past it by a relative 1e-12, so a
// ray through an edge shared by two triangles meets one of them.
double past(double t) { return t + 1e-12 * (1 + std::abs(t)); }

// A layer that changes nothing: no radiance, everything behind passes.
bool is_identity(const physics::SurfaceLayer<double>& l) {
  return is_zero(l.radiance) && l.transmittance == Vec3{1, 1, 1};
}

// A ray leaving `point` along unit `direction`, started past the surface there.
Ray secondary_ray(const Vec3& point, const Vec3& direction) {
  const double size = std::max({std::abs(point[0]), std::abs(point[1]), std::abs(point[2])});
  return {point, direction, kSecondaryRayOffset * (1 + size), std::numeric_limits<double>::infinity()};
}

// The mirror direction of unit `d` about unit `n`: d − 2(d·n) n (RTR4 eq. 11.1's form).
Vec3 reflect(const Vec3& d, const Vec3& n) { return sub(d, scaled(n, 2 * dot(d, n))); }

// The IOR a ray of one colour channel sees (KHR_materials_dispersion's spread,
// physics::dispersed_iors); channel −1 (all three traced together): the one IOR.
double channel_ior(const Translucency& t, int channel) {
  if (channel < 0 || t.dispersion <= 0) return t.ior;
  return physics::dispersed_iors(t.ior, t.dispersion)[size_t(channel)];
}

// The normal an interface refracts about: the shading normal, or the triangle's plane
// where the shading normal faces away from `to_incident` (silhouettes of smooth meshes).
Vec3 interface_normal(const SurfaceHit& hit, const Vec3& to_incident) {
  return dot(hit.normal, to_incident) > 0 ? hit.normal : hit.geometric_normal;
}

}  // namespace

const SurfaceMaterial& Renderer::material_of(const SurfaceHit& hit) const {
  return triangles_.materials[triangles_.attributes[hit.triangle].material];
}

std::optional<SurfaceHit> Renderer::next_surface(const Ray& ray) const {
  const std::optional<TriangleHit> h = camera_bvh_.closest_hit(ray);
  if (!h) return std::nullopt;
  return surface_at(*h, h->triangle, ray.direction);
}

Renderer::SurfaceKind Renderer::surface_kind(const SurfaceHit& hit) const {
  const SurfaceMaterial& m = material_of(hit);
  if (is_hole(triangles_, m, hit.u, hit.v)) return SurfaceKind::hole;
  if (!is_translucent(m)) return SurfaceKind::opaque;
  if (m.translucency.volume == VolumeKind::solid && !hit.front_facing) return SurfaceKind::solid_back_face;
  return SurfaceKind::layer;
}

// The path inside a solid entered at `entry` along `ray`: to its object's next back face or
// the nearer opaque surface; to the ray's end where neither lies ahead, the material's
// thickness for an unbounded ray.
double Renderer::solid_chord(const SurfaceHit& entry, const Ray& ray) const {
  const uint32_t object = triangles_.attributes[entry.triangle].object;
  Ray r = ray;
  r.t_min = past(entry.t);
  while (const std::optional<SurfaceHit> h = next_surface(r)) {
    const SurfaceKind kind = surface_kind(*h);
    if (kind == SurfaceKind::opaque) return h->t - entry.t;
    if (kind == SurfaceKind::solid_back_face && triangles_.attributes[h->triangle].object == object) return h->t - entry.t;
    r.t_min = past(h->t);
  }
  return std::isfinite(ray.t_max) ? ray.t_max - entry.t : thickness_at(triangles_, material_of(entry), entry.u, entry.v);
}

// Beer–Lambert inside the material over `length` m: e^(−σt·length) per channel (RTR4
// eq. 14.23's σt); 1 where there is no extinction or no path.
Vec3 Renderer::inside_transmittance(const SurfaceMaterial& m, double length) const {
  Vec3 t{1, 1, 1};
  for (size_t c = 0; c < 3; ++c) {
    if (m.sigma_t[c] > 0 && length > 0) t[c] = std::exp(-m.sigma_t[c] * length);
  }
  return t;
}

// What physics::surface_layer needs at `hit` for a ray travelling along unit `direction`,
// as shaders/include/translucent_surface.glsl gathers it: F at the cosine between the
// normal (turned toward the ray's origin) and the way back (one interface: no exit F), the
// path inside by the volume kind (`chord` for a solid, taken at the refracted angle). `lit`: the
// radiance's inputs too (irradiance, environment, emission), else only the transmittance's.
physics::LayerInputs<double> Renderer::layer_inputs(const SurfaceHit& hit, const Vec3& direction, double chord, bool lit, int channel) const {
  const SurfaceMaterial& m = material_of(hit);
  const Translucency& tr = m.translucency;
  const double ior = channel_ior(tr, channel);
  const double cos_view = std::clamp(-dot(hit.normal, direction), 0.0, 1.0);
  physics::LayerInputs<double> in;
  in.alpha = layer_coverage(triangles_, m, hit.u, hit.v);
  in.transmission = transmission_at(triangles_, m, hit.u, hit.v);
  in.albedo = albedo_at(triangles_, m, hit.u, hit.v);
  if (lit) {
    in.emissive = emission_at(triangles_, m, hit.u, hit.v);
    in.irradiance = surface_irradiance(hit.position, hit.normal);
    in.environment = integration_.directional_environment ? miss_radiance(reflect(direction, hit.normal)) : environment_;
  }
  in.reflectance = physics::interface_reflectance(ior, cos_view);
  double path = 0;
  if (tr.volume == VolumeKind::shell) path = physics::shell_path_length(thickness_at(triangles_, m, hit.u, hit.v), ior, cos_view);
  if (tr.volume == VolumeKind::solid) path = physics::solid_path_length(chord, ior, cos_view);  // refracted, as the passes
  in.path_transmittance = inside_transmittance(m, path);
  return in;
}

// ---- straight mode ----

Renderer::LayeredRay Renderer::layers_along(const Vec3& direction) const {
  const Camera& camera = scene_.camera;
  const double along_axis = dot(direction, physics::normalize(sub(camera.target, camera.position)));
  LayeredRay out;
  if (along_axis <= 0) return out;
  Ray ray{camera.position, direction, camera.near / along_axis, camera.far / along_axis};
  while (const std::optional<SurfaceHit> hit = next_surface(ray)) {
    const SurfaceKind kind = surface_kind(*hit);
    if (kind == SurfaceKind::opaque) {
      out.end = hit;
      return out;
    }
    if (kind == SurfaceKind::layer) {
      const double chord = material_of(*hit).translucency.volume == VolumeKind::solid ? solid_chord(*hit, ray) : 0;
      const physics::SurfaceLayer<double> layer = physics::surface_layer(layer_inputs(*hit, direction, chord, true));
      if (!is_identity(layer)) {
        if (out.layers.size() >= integration_.max_layers) return out;  // the rest: the background
        out.layers.push_back({hit->t, layer});
      }
    }
    ray.t_min = past(hit->t);
  }
  return out;
}

// C = radiance + transmittance ⊙ C_behind from the farthest layer to the nearest, each
// layer fogged by the media and air in front of it (physics::fogged_layer).
Vec3 Renderer::straight_ray_radiance(const Vec3& direction) const {
  const LayeredRay ray = layers_along(direction);
  Vec3 c = ray_end_radiance(direction, ray.end);
  if (clouds_) {  // as cloud_march + fog_apply compose it: C_behind · T + the layer's in-scattering
    const CloudSample cloud = clouds_->along(direction, ray.end ? ray.end->t : std::numeric_limits<double>::infinity());
    c = add(cloud.radiance, scaled(c, cloud.transmittance));
  }
  const bool fogged = atmosphere_ || !media_.empty();
  for (auto k = ray.layers.rbegin(); k != ray.layers.rend(); ++k) {
    physics::SurfaceLayer<double> layer = k->layer;
    if (fogged) {
      const RayFog fog = camera_fog(direction, k->t);
      layer = physics::fogged_layer(layer, fog.in_scattered, fog.transmittance);
    }
    c = add(layer.radiance, times(layer.transmittance, c));
  }
  return c;
}

// ---- shadow rays ----

// The product of the translucent shadow casters' layer transmittances along `ray` (its
// direction toward the light), 0 at an opaque one: straight on, no refraction.
Vec3 Renderer::shadow_ray_transmittance(const Ray& ray) const {
  Vec3 passed{1, 1, 1};
  Ray r = ray;
  uint32_t crossed = 0;
  while (const std::optional<TriangleHit> h = shadow_bvh_.closest_hit(r)) {
    const SurfaceHit hit = surface_at(*h, shadow_triangles_[h->triangle], r.direction);
    r.t_min = past(h->t);
    const SurfaceKind kind = surface_kind(hit);
    if (kind == SurfaceKind::opaque) return {0, 0, 0};
    if (kind != SurfaceKind::layer || !integration_.translucent_shadows) continue;
    if (++crossed > integration_.max_layers) return {0, 0, 0};
    const double chord = material_of(hit).translucency.volume == VolumeKind::solid ? solid_chord(hit, ray) : 0;
    passed = times(passed, physics::surface_layer(layer_inputs(hit, ray.direction, chord, false)).transmittance);
    if (is_zero(passed)) return passed;
  }
  return passed;
}

// ---- refracted mode ----

Vec3 Renderer::miss_radiance(const Vec3& direction) const {
  if (!atmosphere_) return scene_.background;
  const Vec3 eye = planet_position(atmosphere_->atmosphere(), scene_.camera.position);
  return atmosphere_->sky(eye, direction, camera_ray_key(direction)).radiance;
}

// What arrives at the ray's point `start` from its point `end`, through the media between.
Vec3 Renderer::segment_with_media(const Ray& ray, double start, double end, const Vec3& end_radiance) const {
  if (media_.empty() || !(end > start)) return end_radiance;
  const Vec3 origin = add(ray.origin, scaled(ray.direction, start));
  std::vector<double> breaks;
  for (const Light& light : scene_.lights) {
    if (light.type != LightType::directional) breaks.push_back(dot(sub(light.position, origin), ray.direction));
  }
  const RayScattering media = integrate_single_scattering(
      media_, origin, ray.direction, end - start, std::move(breaks),
      [&](const Vec3& x) { return in_scattering(x, ray.direction); }, integration_);
  return add(media.radiance, times(media.transmittance, end_radiance));
}

Vec3 Renderer::refracted_ray_radiance(const Vec3& direction) const {
  const Camera& camera = scene_.camera;
  const double along_axis = dot(direction, physics::normalize(sub(camera.target, camera.position)));
  if (along_axis <= 0) return ray_end_radiance(direction, std::nullopt);
  const Ray ray{camera.position, direction, camera.near / along_axis, camera.far / along_axis};
  return dispersive_ ? refracted_trace_per_channel(ray) : refracted_trace(ray, 0, {});
}

// A dispersive scene (KHR_materials_dispersion): each channel's ray is traced on its own,
// every medium at that channel's IOR (physics::dispersed_iors), and keeps its own channel.
Vec3 Renderer::refracted_trace_per_channel(const Ray& ray) const {
  Vec3 c{0, 0, 0};
  for (int channel = 0; channel < 3; ++channel) {
    PathState state;
    state.channel = channel;
    c[size_t(channel)] = refracted_trace(ray, 0, state)[size_t(channel)];
  }
  return c;
}

// The radiance arriving at the ray's point `segment_start` along it: surfaces as in
// straight mode, except that a solid of ior ≠ 1 is an interface.
Vec3 Renderer::refracted_trace(const Ray& ray, double segment_start, PathState state) const {
  const std::optional<SurfaceHit> hit = next_surface(ray);
  const double end = hit ? hit->t : std::isfinite(ray.t_max) ? ray.t_max : scene_.camera.far;
  if (!hit) return segment_with_media(ray, segment_start, end, miss_radiance(ray.direction));
  Ray beyond = ray;
  beyond.t_min = past(hit->t);
  const SurfaceKind kind = surface_kind(*hit);
  const SurfaceMaterial& m = material_of(*hit);
  const bool interface = m.translucency.volume == VolumeKind::solid && channel_ior(m.translucency, state.channel) != 1;
  if (kind == SurfaceKind::opaque) return segment_with_media(ray, segment_start, end, surface_radiance(*hit));
  if (kind == SurfaceKind::hole || (kind == SurfaceKind::solid_back_face && !interface)) {
    return refracted_trace(beyond, segment_start, state);
  }
  if (kind == SurfaceKind::solid_back_face) {  // the ray started inside this solid (the camera inside it)
    const Vec3 leaving = leave_solid(*hit, ray.direction, state);
    return times(inside_transmittance(m, hit->t - segment_start), leaving);
  }
  if (interface) return segment_with_media(ray, segment_start, end, enter_solid(*hit, ray.direction, state));
  // A thin wall, a shell or a solid of ior 1: a layer, as in straight mode.
  const double chord = m.translucency.volume == VolumeKind::solid ? solid_chord(*hit, ray) : 0;
  const physics::SurfaceLayer<double> layer = physics::surface_layer(layer_inputs(*hit, ray.direction, chord, true, state.channel));
  if (is_identity(layer)) return segment_with_media(ray, segment_start, end, refracted_trace(beyond, end, state));
  if (++state.layers > integration_.max_layers) return segment_with_media(ray, segment_start, end, miss_radiance(ray.direction));
  state.weight *= largest(layer.transmittance);
  const Vec3 behind = refracted_trace(beyond, end, state);
  return segment_with_media(ray, segment_start, end, add(layer.radiance, times(layer.transmittance, behind)));
}

// Entering a solid at its front face: the layer's reflection (F·L_env), diffuse part and
// emission, and its transmittance (1 − α) + α(1 − F)·t·ρ of the ray refracted inside by
// Bec's form with 1/ior (RTR4 eq. 14.28–14.29); its exit factor and Beer–Lambert are
// applied along the refracted path. The uncovered part (α < 1) enters refracted too.
Vec3 Renderer::enter_solid(const SurfaceHit& entry, const Vec3& direction, PathState state) const {
  const SurfaceMaterial& m = material_of(entry);
  physics::LayerInputs<double> in = layer_inputs(entry, direction, 0, true, state.channel);
  in.path_transmittance = {1, 1, 1};
  const physics::SurfaceLayer<double> layer = physics::surface_layer(in);
  if (++state.bounces > integration_.max_bounces) return layer.radiance;
  const Vec3 to_incident = scaled(direction, -1);
  const std::optional<Vec3> inside = physics::refract_bec(to_incident, interface_normal(entry, to_incident), 1 / channel_ior(m.translucency, state.channel));
  if (!inside || is_zero(layer.transmittance)) return layer.radiance;
  state.weight *= largest(layer.transmittance);
  const Vec3 through = inside_solid(secondary_ray(entry.position, physics::normalize(*inside)), triangles_.attributes[entry.triangle].object, m, state);
  return add(layer.radiance, times(layer.transmittance, through));
}

// Along `ray` inside the solid `object`: Beer–Lambert to the first opaque surface (its
// radiance) or the object's back face (leave_solid there); surfaces of other objects
// inside are passed. An open mesh with no back face ahead: the thickness, then the
// background.
Vec3 Renderer::inside_solid(const Ray& ray, uint32_t object, const SurfaceMaterial& medium, PathState state) const {
  Ray r = ray;
  while (const std::optional<SurfaceHit> h = next_surface(r)) {
    const SurfaceKind kind = surface_kind(*h);
    const bool own = triangles_.attributes[h->triangle].object == object;
    if (kind == SurfaceKind::opaque) return times(inside_transmittance(medium, h->t), surface_radiance(*h));
    if (kind == SurfaceKind::solid_back_face && own) return times(inside_transmittance(medium, h->t), leave_solid(*h, ray.direction, state));
    r.t_min = past(h->t);
  }
  return {0, 0, 0};  // no way out: an open mesh's inside sees nothing
}

// Leaving a solid at `exit` (a back face, its normal turned inward) along `direction`:
// refracted out by Bec's form with eta = ior, (1 − F) of what lies outside with F by
// Schlick at the outside angle, plus F of the ray reflected back inside while its weight
// lasts; total internal reflection sends all of it back inside.
Vec3 Renderer::leave_solid(const SurfaceHit& exit, const Vec3& direction, PathState state) const {
  if (++state.bounces > integration_.max_bounces) return {0, 0, 0};
  const SurfaceMaterial& m = material_of(exit);
  const uint32_t object = triangles_.attributes[exit.triangle].object;
  const Vec3 to_incident = scaled(direction, -1);
  const Vec3 n = interface_normal(exit, to_incident);
  const Vec3 mirrored = physics::normalize(reflect(direction, n));
  const double ior = channel_ior(m.translucency, state.channel);
  const std::optional<Vec3> out = physics::refract_bec(to_incident, n, ior);
  if (!out) return inside_solid(secondary_ray(exit.position, mirrored), object, m, state);  // total internal reflection
  const Vec3 outward = physics::normalize(*out);
  const double f = physics::interface_reflectance(ior, std::abs(dot(outward, n)));
  PathState outside = state;
  outside.weight *= 1 - f;
  Vec3 c = scaled(refracted_trace(secondary_ray(exit.position, outward), 0, outside), 1 - f);
  if (f * state.weight > integration_.min_branch_weight) {
    PathState back = state;
    back.weight *= f;
    c = add(c, scaled(inside_solid(secondary_ray(exit.position, mirrored), object, m, back), f));
  }
  return c;
}

}  // namespace volgraph::reference
