// CPU twin of shaders/include/lighting.glsl (DESIGN.md units). Change both together.
#pragma once

#include <algorithm>
#include <cmath>

#include "graph/scene/scene.h"
#include "physics/camera.h"

namespace volgraph::physics {

// The most lights a scene may have (MAX_LIGHTS in light_list.glsl; the scene reader checks it).
constexpr int kMaxLights = 16;

inline double smoothstep(double e0, double e1, double x) {
  const double t = glm::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// What one light delivers at `p`, unshadowed: the irradiance E on a surface facing it
// (directional: E; point and spot: I/d², spot with a smooth cone falloff), and the unit
// direction its light travels there.
struct LightArriving {
  Vec3 irradiance;
  Vec3 travel;
};

inline LightArriving light_arriving(const Light& light, const Vec3& p) {
  if (light.type == LightType::directional) return {light.irradiance, to_vec3(glm::normalize(vec(light.direction)))};
  const glm::dvec3 from_light = vec(p) - vec(light.position);
  const double d2 = std::max(glm::dot(from_light, from_light), 1e-12);
  const glm::dvec3 travel = glm::normalize(from_light);
  double cone = 1.0;
  if (light.type == LightType::spot) {
    cone = smoothstep(std::cos(light.outer_cone_deg * M_PI / 180), std::cos(light.inner_cone_deg * M_PI / 180),
                      glm::dot(travel, glm::normalize(vec(light.direction))));
  }
  return {to_vec3(vec(light.intensity) * (cone / d2)), to_vec3(travel)};
}

// Irradiance on a surface at `p` with unit normal `n` from one light, unshadowed: E·cos θ.
inline Vec3 irradiance(const Light& light, const Vec3& p, const Vec3& n) {
  const LightArriving a = light_arriving(light, p);
  const double c = std::max(-glm::dot(vec(n), vec(a.travel)), 0.0);
  return to_vec3(vec(a.irradiance) * c);
}

// A Lambertian surface of albedo ρ under irradiance E reflects ρ/π · E.
inline Vec3 lambert(const Vec3& albedo, const Vec3& e) { return to_vec3(vec(albedo) / M_PI * vec(e)); }

}  // namespace volgraph::physics
