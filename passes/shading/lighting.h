// CPU twin of shaders/include/lighting.glsl (DESIGN.md units). Change both together.
#pragma once

#include <algorithm>
#include <cmath>

#include "graph/scene/scene.h"
#include "passes/shading/camera.h"

namespace volgraph::shading {

inline double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// Irradiance on a surface at `p` with unit normal `n` from one light, unshadowed: E·cos θ.
inline Vec3 irradiance(const Light& light, const Vec3& p, const Vec3& n) {
  if (light.type == LightType::directional) {
    const Vec3 dir = normalize(light.direction);
    const double c = std::max(-dot(n, dir), 0.0);
    return {light.irradiance[0] * c, light.irradiance[1] * c, light.irradiance[2] * c};
  }
  const Vec3 to_light = sub(light.position, p);
  const double d2 = std::max(dot(to_light, to_light), 1e-12);
  const Vec3 l = normalize(to_light);
  double cone = 1.0;
  if (light.type == LightType::spot) {
    const Vec3 dir = normalize(light.direction);
    cone = smoothstep(std::cos(light.outer_cone_deg * M_PI / 180), std::cos(light.inner_cone_deg * M_PI / 180),
                      -dot(l, dir));
  }
  const double f = cone * std::max(dot(n, l), 0.0) / d2;
  return {light.intensity[0] * f, light.intensity[1] * f, light.intensity[2] * f};
}

// A Lambertian surface of albedo ρ under irradiance E reflects ρ/π · E.
inline Vec3 lambert(const Vec3& albedo, const Vec3& e) {
  return {albedo[0] / M_PI * e[0], albedo[1] / M_PI * e[1], albedo[2] / M_PI * e[2]};
}

}  // namespace volgraph::shading
