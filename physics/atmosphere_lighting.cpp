#include "physics/atmosphere_lighting.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "physics/atmosphere.h"
#include "physics/atmosphere_multiscattering.h"
#include "physics/vec3.h"

namespace volgraph::physics {
namespace {

// The atmosphere's sun at the scene's origin: its light, the radius there and the sun's
// zenith cosine (the origin's zenith is +y); none when the atmosphere names no sun.
struct SunAtOrigin {
  const Light* light = nullptr;
  double r = 0;
  double mu_s = -1;
};

std::optional<SunAtOrigin> sun_at_origin(const Scene& scene) {
  if (!scene.atmosphere) return std::nullopt;
  const Atmosphere& a = *scene.atmosphere;
  if (a.sun_light < 0 || size_t(a.sun_light) >= scene.lights.size()) return std::nullopt;
  const Light& light = scene.lights[size_t(a.sun_light)];
  const Vec3& d = light.direction;
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(length > 0)) return std::nullopt;
  return SunAtOrigin{&light, a.bottom_radius + std::max(a.origin_altitude, 0.0), std::clamp(-d[1] / length, -1.0, 1.0)};
}


}  // namespace

std::vector<Light> lights_through_atmosphere(const Scene& scene) {
  std::vector<Light> lights = scene.lights;
  const std::optional<SunAtOrigin> sun = sun_at_origin(scene);
  if (!sun) return lights;
  Light& light = lights[size_t(scene.atmosphere->sun_light)];
  light.irradiance = times(light.irradiance, sun_transmittance(*scene.atmosphere, sun->r, sun->mu_s));
  return lights;
}

Vec3 sky_ambient_radiance(const Scene& scene) {
  const std::optional<SunAtOrigin> sun = sun_at_origin(scene);
  if (!sun) return {0, 0, 0};
  return times(sun->light->irradiance, multiscattering(*scene.atmosphere, sun->r, sun->mu_s));
}

LightAtAltitude atmosphere_light_at_altitude(const Scene& scene, double altitude) {
  const std::optional<SunAtOrigin> sun = sun_at_origin(scene);
  if (!sun) return {};
  const Atmosphere& a = *scene.atmosphere;
  // Inside the air: the tables' radii run from the ground to the top of the atmosphere.
  const double r = std::clamp(a.bottom_radius + std::max(altitude, 0.0), a.bottom_radius, a.top_radius);
  const Vec3& e = sun->light->irradiance;
  return {true, times(e, sun_transmittance(a, r, sun->mu_s)), times(e, multiscattering(a, r, sun->mu_s))};
}

}  // namespace volgraph::physics
