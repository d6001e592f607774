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
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
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
  if (light.type == LightType::directional) return {light.irradiance, normalize(light.direction)};
  const Vec3 from_light = sub(p, light.position);
  const double d2 = std::max(dot(from_light, from_light), 1e-12);
  const Vec3 travel = normalize(from_light);
  double cone = 1.0;
  if (light.type == LightType::spot) {
    cone = smoothstep(std::cos(light.outer_cone_deg * M_PI / 180), std::cos(light.inner_cone_deg * M_PI / 180),
                      dot(travel, normalize(light.direction)));
  }
  const double f = cone / d2;
  return {{light.intensity[0] * f, light.intensity[1] * f, light.intensity[2] * f}, travel};
}

// Irradiance on a surface at `p` with unit normal `n` from one light, unshadowed: E·cos θ.
inline Vec3 irradiance(const Light& light, const Vec3& p, const Vec3& n) {
  const LightArriving a = light_arriving(light, p);
  const double c = std::max(-dot(n, a.travel), 0.0);
  return {a.irradiance[0] * c, a.irradiance[1] * c, a.irradiance[2] * c};
}

// A Lambertian surface of albedo ρ under irradiance E reflects ρ/π · E.
inline Vec3 lambert(const Vec3& albedo, const Vec3& e) {
  return {albedo[0] / M_PI * e[0], albedo[1] / M_PI * e[1], albedo[2] / M_PI * e[2]};
}

}  // namespace volgraph::physics
