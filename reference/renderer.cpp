#include "reference/renderer.h"

#include <algorithm>
#include <cmath>

#include "physics/camera.h"
#include "physics/lighting.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::dot;
using physics::normalize;
using physics::scaled;
using physics::sub;

constexpr double kShadowRayOffset = 1e-9;  // metres per metre of |point|∞, plus 1e-9 m

std::vector<Triangle> shadow_casters(const SceneTriangles& scene) {
  std::vector<Triangle> casters;
  for (size_t i = 0; i < scene.triangles.size(); ++i) {
    if (scene.casts_shadows[i]) casters.push_back(scene.triangles[i]);
  }
  return casters;
}

Vec3 interpolate(const std::array<Vec3, 3>& corners, double u, double v) {
  return add(add(scaled(corners[0], 1 - u - v), scaled(corners[1], u)), scaled(corners[2], v));
}

bool is_zero(const Vec3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }
Vec3 times(const Vec3& a, const Vec3& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }

// Optical depth of the media from `point` to the light.
Vec3 optical_depth_toward(const SceneMedia& media, const Light& light, const Vec3& point) {
  const Vec3 to_light = scaled(physics::light_arriving(light, point).travel, -1);
  if (light.type == LightType::directional) return media.optical_depth_to_infinity(point, to_light);
  return media.optical_depth(point, to_light, 0, std::sqrt(dot(sub(light.position, point), sub(light.position, point))));
}

// The camera's view axis, unit.
Vec3 forward(const Camera& camera) { return normalize(sub(camera.target, camera.position)); }

}  // namespace

Renderer::Renderer(const Scene& scene, const IntegrationSettings& integration)
    : scene_(scene),
      triangles_(scene_triangles(scene)),
      camera_bvh_(triangles_.triangles),
      shadow_bvh_(shadow_casters(triangles_)),
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
  const std::optional<SurfaceHit> hit = surface_hit(direction);
  const Vec3 behind = hit ? surface_radiance(*hit) : scene_.background;
  if (media_.empty()) return behind;
  const Camera& camera = scene_.camera;
  const double along_axis = dot(direction, forward(camera));
  const double length = hit ? hit->t : along_axis > 0 ? camera.far / along_axis : 0;
  // The in-scattering of a point or spot light peaks where the ray passes closest to it.
  std::vector<double> breaks;
  for (const Light& light : scene_.lights) {
    if (light.type != LightType::directional) breaks.push_back(dot(sub(light.position, camera.position), direction));
  }
  const RayScattering media = integrate_single_scattering(
      media_, camera.position, direction, length, std::move(breaks), [&](const Vec3& x) { return in_scattering(x, direction); },
      integration_);
  return add(media.radiance, times(media.transmittance, behind));
}

std::optional<SurfaceHit> Renderer::surface_hit(const Vec3& direction) const {
  const Camera& camera = scene_.camera;
  const double along_axis = dot(direction, forward(camera));
  if (along_axis <= 0) return std::nullopt;
  const Ray ray{camera.position, direction, camera.near / along_axis, camera.far / along_axis};
  const std::optional<TriangleHit> h = camera_bvh_.closest_hit(ray);
  if (!h) return std::nullopt;
  const Triangle& tri = triangles_.triangles[h->triangle];
  const TriangleAttributes& a = triangles_.attributes[h->triangle];
  SurfaceHit s;
  s.t = h->t;
  s.triangle = h->triangle;
  s.position = interpolate({tri.a, tri.b, tri.c}, h->u, h->v);
  const Vec3 geometric = physics::cross(sub(tri.b, tri.a), sub(tri.c, tri.a));
  const Vec3 interpolated = interpolate(a.normals, h->u, h->v);
  s.normal = normalize(dot(interpolated, interpolated) > 0 ? interpolated : geometric);
  // Two-sided like the GPU: seen from the back (clockwise on screen), the normal turns.
  if (dot(geometric, direction) > 0) s.normal = scaled(s.normal, -1);
  s.u = (1 - h->u - h->v) * a.uvs[0][0] + h->u * a.uvs[1][0] + h->v * a.uvs[2][0];
  s.v = (1 - h->u - h->v) * a.uvs[0][1] + h->u * a.uvs[1][1] + h->v * a.uvs[2][1];
  return s;
}

Vec3 Renderer::surface_radiance(const SurfaceHit& hit) const {
  Vec3 e{0, 0, 0};
  for (const Light& light : scene_.lights) e = add(e, light_arrival(light, hit.position, hit.normal));
  const SurfaceMaterial& m = triangles_.materials[triangles_.attributes[hit.triangle].material];
  return add(physics::lambert(albedo_at(triangles_, m, hit.u, hit.v), e), emission_at(triangles_, m, hit.u, hit.v));
}

Vec3 Renderer::light_arrival(const Light& light, const Vec3& point, const Vec3& normal) const {
  const Vec3 unshadowed = physics::irradiance(light, point, normal);
  if (is_zero(unshadowed) || !light_visible(light, point)) return {0, 0, 0};
  if (media_.empty()) return unshadowed;
  return times(unshadowed, transmittance_of(optical_depth_toward(media_, light, point)));
}

Vec3 Renderer::in_scattering(const Vec3& point, const Vec3& direction) const {
  Vec3 j = media_.at(point).emission;
  for (const Light& light : scene_.lights) {
    if (light.type != LightType::directional && point == light.position) continue;  // no direction: a singular point
    const physics::LightArriving arriving = physics::light_arriving(light, point);
    const Vec3 sigma_s_phase = media_.scattering(point, -dot(arriving.travel, direction));
    if (is_zero(sigma_s_phase) || is_zero(arriving.irradiance) || !light_visible(light, point)) continue;
    const Vec3 through = media_.empty() ? Vec3{1, 1, 1} : transmittance_of(optical_depth_toward(media_, light, point));
    j = add(j, times(sigma_s_phase, times(arriving.irradiance, through)));
  }
  return j;
}

bool Renderer::light_visible(const Light& light, const Vec3& point) const {
  if (!light.cast_shadows) return true;
  const double size = std::max({std::abs(point[0]), std::abs(point[1]), std::abs(point[2])});
  Ray ray{point, {0, 0, 0}, kShadowRayOffset * (1 + size), std::numeric_limits<double>::infinity()};
  if (light.type == LightType::directional) {
    ray.direction = scaled(normalize(light.direction), -1);
  } else {
    const Vec3 to_light = sub(light.position, point);
    const double distance = std::sqrt(dot(to_light, to_light));
    if (distance == 0) return true;
    ray.direction = scaled(to_light, 1 / distance);
    ray.t_max = distance;
  }
  return !shadow_bvh_.any_hit(ray);
}

}  // namespace volgraph::reference
