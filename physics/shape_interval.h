// Where a ray runs inside a medium volume's shape (CPU twin of
// shaders/include/shape_interval.glsl): the parameter interval [enter, exit] of
// origin + t·direction (direction of any length, not 0) inside the unit shape — the box
// of edges 1 by slabs (Kay & Kajiya 1986), the ball of radius 1 by the quadratic — in
// that shape's space. A volume's shape is its unit shape scaled by unit_shape_scale,
// then carried into the world by its transform; affine maps keep t, so an interval found
// in the unit shape's space holds for the world ray too. Double precision; the reference
// (reference/media.cpp) and the froxel average (physics/media_average.h) use it.
#pragma once

#include <optional>

#include "graph/scene/scene.h"

namespace volgraph::physics {

// A parameter interval [enter, exit] of a ray, enter ≤ exit.
struct RayInterval {
  double enter = 0, exit = 0;
};

// The box |x|, |y|, |z| ≤ ½: the slabs' intervals intersected (Kay & Kajiya 1986).
std::optional<RayInterval> unit_box_interval(const Vec3& origin, const Vec3& direction);
// The ball |p| ≤ 1: |o + t·d|² = 1, roots by the cancellation-free quadratic formula
// (Press et al., Numerical Recipes, 3rd ed., eq. 5.6.4–5.6.5).
std::optional<RayInterval> unit_ball_interval(const Vec3& origin, const Vec3& direction);
// The box for Shape::box, the ball for the sphere and the ellipsoid.
std::optional<RayInterval> unit_shape_interval(Shape shape, const Vec3& origin, const Vec3& direction);

// A volume's size as a scale of its unit shape: box edges, a sphere's radius (its first
// size), an ellipsoid's radii (local units per unit-shape unit).
Vec3 unit_shape_scale(const MediumVolume& v);

}  // namespace volgraph::physics
