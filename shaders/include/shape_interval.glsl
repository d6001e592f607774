// Where a ray runs inside a medium volume's unit shape: the parameter interval
// (enter, exit) of origin + t·direction inside the box of edges 1 (slabs, Kay & Kajiya
// 1986) or the ball of radius 1 (the cancellation-free quadratic, Press et al.,
// Numerical Recipes, 3rd ed., eq. 5.6.4–5.6.5); enter > exit where the ray misses.
// CPU twin: physics/shape_interval.h.
#ifndef VOLGRAPH_SHAPE_INTERVAL_GLSL
#define VOLGRAPH_SHAPE_INTERVAL_GLSL

const vec2 NO_INTERVAL = vec2(1.0, -1.0);

vec2 unit_box_interval(vec3 o, vec3 d) {
  float enter = -3.4e38, exit = 3.4e38;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (abs(o[k]) > 0.5) return NO_INTERVAL;
      continue;
    }
    const float a = (-0.5 - o[k]) / d[k], b = (0.5 - o[k]) / d[k];
    enter = max(enter, min(a, b));
    exit = min(exit, max(a, b));
  }
  return enter > exit ? NO_INTERVAL : vec2(enter, exit);
}

vec2 unit_ball_interval(vec3 o, vec3 d) {
  const float a = dot(d, d), b = 2.0 * dot(o, d), c = dot(o, o) - 1.0;
  const float discriminant = b * b - 4.0 * a * c;
  if (a == 0.0 || discriminant < 0.0) return NO_INTERVAL;
  const float q = -(b + (b < 0.0 ? -1.0 : 1.0) * sqrt(discriminant)) / 2.0;
  if (q == 0.0) return vec2(0.0);
  const float r1 = q / a, r2 = c / q;
  return vec2(min(r1, r2), max(r1, r2));
}

#endif
