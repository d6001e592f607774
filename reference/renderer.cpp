#include "reference/renderer.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "physics/atmosphere_lighting.h"
#include "physics/camera.h"
#include "physics/lighting.h"
#include "reference/atmosphere_reference.h"
#include "reference/clouds.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::dot;
using physics::normalize;
using physics::scaled;
using physics::sub;
using physics::times;
using physics::is_zero;

constexpr double kShadowRayOffset = 1e-9;  // metres per metre of |point|∞, plus 1e-9 m

std::vector<uint32_t> shadow_caster_indices(const SceneTriangles& scene) {
  std::vector<uint32_t> casters;
  for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
    if (scene.casts_shadows[i]) casters.push_back(i);
  }
  return casters;
}

std::vector<Triangle> shadow_casters(const SceneTriangles& scene) {
  std::vector<Triangle> casters;
  for (const uint32_t i : shadow_caster_indices(scene)) casters.push_back(scene.triangles[i]);
  return casters;
}

bool any_dispersive(const SceneTriangles& scene) {
  for (const SurfaceMaterial& m : scene.materials) {
    if (m.translucency.dispersion > 0) return true;
  }
  return false;
}

bool any_see_through(const SceneTriangles& scene, const std::vector<uint32_t>& casters) {
  for (const uint32_t i : casters) {
    const SurfaceMaterial& m = scene.materials[scene.attributes[i].material];
    if (is_translucent(m) || m.translucency.alpha_mode == AlphaMode::mask) return true;
  }
  return false;
}

Vec3 interpolate(const std::array<Vec3, 3>& corners, double u, double v) {
  return add(add(scaled(corners[0], 1 - u - v), scaled(corners[1], u)), scaled(corners[2], v));
}


// Optical depth of the media from `point` to the light.
Vec3 optical_depth_toward(const SceneMedia& media, const Light& light, const Vec3& point) {
  const Vec3 to_light = scaled(physics::light_arriving(light, point).travel, -1);
  if (light.type == LightType::directional) return media.optical_depth_to_infinity(point, to_light);
  return media.optical_depth(point, to_light, 0, std::sqrt(dot(sub(light.position, point), sub(light.position, point))));
}

// The camera's view axis, unit.
Vec3 forward(const Camera& camera) { return normalize(sub(camera.target, camera.position)); }

// The atmosphere's reference for the scene: its sun the scene's sun light as it is at the
// top of the atmosphere (a sun of no light where the atmosphere names none: the air still
// dims); null without an atmosphere.
std::shared_ptr<const AtmosphereReference> atmosphere_reference(const Scene& scene, const AtmosphereReferenceSettings& settings) {
  if (!scene.atmosphere) return nullptr;
  const Atmosphere& a = *scene.atmosphere;
  const AtmosphereSun sun = scene_sun(a, scene.lights).value_or(AtmosphereSun{{0, 1, 0}, {0, 0, 0}, a.sun_angular_radius});
  return std::make_shared<const AtmosphereReference>(a, sun, settings);
}

// The air's orders ≥ 2 along a camera ray: A(t), the light they add on [0, t], at nodes.
struct AirProfile {
  std::vector<double> t;
  std::vector<Vec3> light;
  Vec3 at(double x) const {
    if (x <= 0 || t.size() < 2) return {0, 0, 0};
    const size_t k = std::min(size_t(std::upper_bound(t.begin(), t.end(), x) - t.begin()), t.size() - 1);
    const double w = std::clamp((x - t[k - 1]) / (t[k] - t[k - 1]), 0.0, 1.0);
    return add(scaled(light[k - 1], 1 - w), scaled(light[k], w));
  }
};

Vec3 multiple_orders(const ScatteringOrders& s) { return sub(s.total, s.radiance.empty() ? Vec3{0, 0, 0} : s.radiance[0]); }

}  // namespace

uint64_t camera_ray_key(const Vec3& direction) {
  const auto bits = [&](int c) { return std::bit_cast<uint64_t>(direction[size_t(c)]); };
  return bits(0) ^ std::rotl(bits(1), 21) ^ std::rotl(bits(2), 42);
}

Renderer::Renderer(const Scene& scene, const IntegrationSettings& integration)
    : Renderer(scene, integration, AtmosphereReferenceSettings{}) {}

Renderer::Renderer(const Scene& scene, const IntegrationSettings& integration, const AtmosphereReferenceSettings& atmosphere)
    : scene_(scene),
      lights_(physics::lights_through_atmosphere(scene)),
      sky_ambient_(physics::sky_ambient_radiance(scene)),
      atmosphere_(atmosphere_reference(scene, atmosphere)),
      clouds_(scene.clouds ? std::make_shared<const CloudReference>(scene, integration.clouds) : nullptr),
      triangles_(scene_triangles(scene)),
      camera_bvh_(triangles_.triangles),
      shadow_bvh_(shadow_casters(triangles_)),
      shadow_triangles_(shadow_caster_indices(triangles_)),
      see_through_casters_(any_see_through(triangles_, shadow_triangles_)),
      dispersive_(any_dispersive(triangles_)),
      environment_(scene.atmosphere ? sky_ambient_ : scene.background),
      media_(scene.media),
      integration_(integration) {}

Vec3 Renderer::pixel_radiance(uint32_t i, uint32_t j, uint32_t width, uint32_t height, uint32_t samples_per_axis) const {
  Vec3 sum{0, 0, 0};
  const uint32_t n = std::max(samples_per_axis, 1u);
  for (uint32_t sy = 0; sy < n; ++sy) {
    for (uint32_t sx = 0; sx < n; ++sx) {
      // pixel_ray adds the half pixel of the centre: offsets are relative to it.
      const double x = i + (sx + 0.5) / n - 0.5, y = j + (sy + 0.5) / n - 0.5;
      sum = add(sum, camera_ray_radiance(physics::pixel_ray(scene_.camera, width, height, x, y)));
    }
  }
  return scaled(sum, 1.0 / (n * n));
}

Vec3 Renderer::camera_ray_radiance(const Vec3& direction) const {
  if (integration_.translucency == TranslucencyMode::refracted) return refracted_ray_radiance(direction);
  return straight_ray_radiance(direction);
}

double Renderer::far_length(const Vec3& direction) const {
  const double along_axis = dot(direction, forward(scene_.camera));
  return along_axis > 0 ? scene_.camera.far / along_axis : 0;
}

Renderer::RayFog Renderer::camera_fog(const Vec3& direction, double length) const {
  if (atmosphere_) return atmosphere_fog(direction, length);
  if (media_.empty()) return {};
  const Camera& camera = scene_.camera;
  // The in-scattering of a point or spot light peaks where the ray passes closest to it.
  std::vector<double> breaks;
  for (const Light& light : scene_.lights) {
    if (light.type != LightType::directional) breaks.push_back(dot(sub(light.position, camera.position), direction));
  }
  const RayScattering media = integrate_single_scattering(
      media_, camera.position, direction, length, std::move(breaks), [&](const Vec3& x) { return in_scattering(x, direction); },
      integration_);
  return {media.radiance, media.transmittance};
}

Vec3 Renderer::ray_end_radiance(const Vec3& direction, const std::optional<SurfaceHit>& hit) const {
  const double length = hit ? hit->t : far_length(direction);
  if (atmosphere_) {
    const AtmosphereReference& air = *atmosphere_;
    const Vec3 eye = planet_position(air.atmosphere(), scene_.camera.position);
    const uint64_t key = camera_ray_key(direction);
    if (media_.empty() && !hit) return air.sky(eye, direction, key).radiance;
    const Vec3 behind = hit ? surface_radiance(*hit) : air.sky(add(eye, scaled(direction, length)), direction, key).radiance;
    const RayFog fog = atmosphere_fog(direction, length);
    return add(fog.in_scattered, times(fog.transmittance, behind));
  }
  const Vec3 behind = hit ? surface_radiance(*hit) : scene_.background;
  if (media_.empty()) return behind;
  const RayFog fog = camera_fog(direction, length);
  return add(fog.in_scattered, times(fog.transmittance, behind));
}

Renderer::RayFog Renderer::atmosphere_fog(const Vec3& direction, double length) const {
  const AtmosphereReference& air = *atmosphere_;
  const Atmosphere& a = air.atmosphere();
  const Camera& camera = scene_.camera;
  const Vec3 eye = planet_position(a, camera.position);
  const uint64_t key = camera_ray_key(direction);
  if (media_.empty()) {
    const AerialPerspectiveSample ap = air.aerial_perspective(eye, direction, length, key);
    return {ap.in_scattered, ap.transmittance};
  }
  // The air's orders ≥ 2: A(t) at kAirNodes equal steps, the same paths' seeds at each.
  AirProfile profile{{0}, {{0, 0, 0}}};
  for (int k = 1; k <= kAirNodes && length > 0; ++k) {
    const double t = length * k / kAirNodes;
    profile.t.push_back(t);
    profile.light.push_back(multiple_orders(air.aerial_perspective(eye, direction, t, key).scattering));
  }
  std::vector<double> breaks(profile.t.begin() + 1, profile.t.end() - (profile.t.size() > 1 ? 1 : 0));
  for (const Light& light : scene_.lights) {
    if (light.type != LightType::directional) breaks.push_back(dot(sub(light.position, camera.position), direction));
  }
  // J(t) = T_air(0, t) (J_media + J_air, order 1) + σt_media A(t): with the media's own
  // transmittance applied by the integral, ∫ T_media T_air J dt and ∫ T_media dA by parts.
  const auto source = [&](const Vec3& x) {
    const double t = dot(sub(x, camera.position), direction);
    const Vec3 lit = add(in_scattering(x, direction), air.air_in_scattering(planet_position(a, x), direction));
    const Vec3 dimmed = times(air.transmittance_along(eye, direction, t), lit);
    return add(dimmed, times(media_.at(x).sigma_t(), profile.at(t)));
  };
  const RayScattering media = integrate_single_scattering(media_, camera.position, direction, length, std::move(breaks), source,
                                                          integration_);
  const Vec3 air_to_end = air.transmittance_along(eye, direction, length);
  return {add(media.radiance, times(media.transmittance, profile.at(length))), times(media.transmittance, air_to_end)};
}

std::optional<SurfaceHit> Renderer::surface_hit(const Vec3& direction) const {
  const Camera& camera = scene_.camera;
  const double along_axis = dot(direction, forward(camera));
  if (along_axis <= 0) return std::nullopt;
  const Ray ray{camera.position, direction, camera.near / along_axis, camera.far / along_axis};
  const std::optional<TriangleHit> h = camera_bvh_.closest_hit(ray);
  if (!h) return std::nullopt;
  return surface_at(*h, h->triangle, direction);
}

SurfaceHit Renderer::surface_at(const TriangleHit& h, uint32_t triangle, const Vec3& direction) const {
  const Triangle& tri = triangles_.triangles[triangle];
  const TriangleAttributes& a = triangles_.attributes[triangle];
  SurfaceHit s;
  s.t = h.t;
  s.triangle = triangle;
  s.position = interpolate({tri.a, tri.b, tri.c}, h.u, h.v);
  const Vec3 geometric = physics::cross(sub(tri.b, tri.a), sub(tri.c, tri.a));
  const Vec3 interpolated = interpolate(a.normals, h.u, h.v);
  s.normal = normalize(dot(interpolated, interpolated) > 0 ? interpolated : geometric);
  // Two-sided like the GPU: seen from the back (clockwise on screen), the normal turns.
  s.front_facing = !(dot(geometric, direction) > 0);
  if (!s.front_facing) s.normal = scaled(s.normal, -1);
  s.geometric_normal = normalize(s.front_facing ? geometric : scaled(geometric, -1));
  s.u = (1 - h.u - h.v) * a.uvs[0][0] + h.u * a.uvs[1][0] + h.v * a.uvs[2][0];
  s.v = (1 - h.u - h.v) * a.uvs[0][1] + h.u * a.uvs[1][1] + h.v * a.uvs[2][1];
  return s;
}

Vec3 Renderer::surface_irradiance(const Vec3& point, const Vec3& normal) const {
  Vec3 e{0, 0, 0};
  for (const Light& light : lights_) e = add(e, light_arrival(light, point, normal));
  if (atmosphere_) e = add(e, scaled(sky_ambient_, M_PI));  // an isotropic L: irradiance π·L on any surface
  return e;
}

Vec3 Renderer::surface_radiance(const SurfaceHit& hit) const {
  const Vec3 e = surface_irradiance(hit.position, hit.normal);
  const SurfaceMaterial& m = triangles_.materials[triangles_.attributes[hit.triangle].material];
  return add(physics::lambert(albedo_at(triangles_, m, hit.u, hit.v), e), emission_at(triangles_, m, hit.u, hit.v));
}

Vec3 Renderer::light_arrival(const Light& light, const Vec3& point, const Vec3& normal) const {
  const Vec3 unshadowed = physics::irradiance(light, point, normal);
  if (is_zero(unshadowed)) return {0, 0, 0};
  const Vec3 passed = light_transmittance(light, point);
  if (is_zero(passed)) return {0, 0, 0};
  const Vec3 lit = see_through_casters_ ? times(unshadowed, passed) : unshadowed;
  if (media_.empty()) return lit;
  return times(lit, transmittance_of(optical_depth_toward(media_, light, point)));
}

Vec3 Renderer::in_scattering(const Vec3& point, const Vec3& direction) const {
  const physics::MediaSample sample = media_.at(point);
  Vec3 j = atmosphere_ ? add(sample.emission, times(sample.sigma_s, sky_ambient_)) : sample.emission;
  for (const Light& light : lights_) {
    if (light.type != LightType::directional && point == light.position) continue;  // no direction: a singular point
    const physics::LightArriving arriving = physics::light_arriving(light, point);
    const Vec3 sigma_s_phase = media_.scattering(point, -dot(arriving.travel, direction));
    if (is_zero(sigma_s_phase) || is_zero(arriving.irradiance)) continue;
    const Vec3 passed = light_transmittance(light, point);
    if (is_zero(passed)) continue;
    const Vec3 through_media = media_.empty() ? Vec3{1, 1, 1} : transmittance_of(optical_depth_toward(media_, light, point));
    const Vec3 through = see_through_casters_ ? times(through_media, passed) : through_media;
    j = add(j, times(sigma_s_phase, times(arriving.irradiance, through)));
  }
  return j;
}

bool Renderer::light_visible(const Light& light, const Vec3& point) const { return !is_zero(light_transmittance(light, point)); }

Vec3 Renderer::light_transmittance(const Light& light, const Vec3& point) const {
  if (!light.cast_shadows) return {1, 1, 1};
  const double size = std::max({std::abs(point[0]), std::abs(point[1]), std::abs(point[2])});
  Ray ray{point, {0, 0, 0}, kShadowRayOffset * (1 + size), std::numeric_limits<double>::infinity()};
  if (light.type == LightType::directional) {
    ray.direction = scaled(normalize(light.direction), -1);
  } else {
    const Vec3 to_light = sub(light.position, point);
    const double distance = std::sqrt(dot(to_light, to_light));
    if (distance == 0) return {1, 1, 1};
    ray.direction = scaled(to_light, 1 / distance);
    ray.t_max = distance;
  }
  if (!see_through_casters_) return shadow_bvh_.any_hit(ray) ? Vec3{0, 0, 0} : Vec3{1, 1, 1};
  return shadow_ray_transmittance(ray);
}

}  // namespace volgraph::reference
