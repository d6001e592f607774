// Screen-space light shafts (Mitchell 2007, GPU Gems 3 ch. 13; RTR4 §14.2.2): where the sun
// lies on the screen, how much of the effect is left as it leaves the screen, and what a
// pixel gathers when every sample sees the sky. One text for light_shafts_screen's host
// code and its tests.
#pragma once

#include <algorithm>
#include <cmath>

#include "physics/camera.h"

namespace volgraph::physics {

struct ScreenSun {
  double u = 0.5, v = 0.5;  // the sun's texture coordinate on the frame (u right, v down)
  double fade = 0;          // 1 on screen, falling to 0 `fade_margin` frames past its edge; 0 behind the camera
};

// `to_sun` unit, toward the sun; `fade_margin` in frame widths (0: off as soon as it leaves).
inline ScreenSun screen_sun(const ViewRays& rays, const Vec3& to_sun, double fade_margin) {
  const double facing = to_sun[0] * rays.forward[0] + to_sun[1] * rays.forward[1] + to_sun[2] * rays.forward[2];
  if (!(facing > 0)) return {};
  const Vec3 p{rays.position[0] + to_sun[0], rays.position[1] + to_sun[1], rays.position[2] + to_sun[2]};
  const ViewUvz s = view_uvz(rays, p);
  const double outside = std::max({-s.u, s.u - 1, -s.v, s.v - 1, 0.0});
  const double fade = fade_margin > 0 ? std::clamp(1 - outside / fade_margin, 0.0, 1.0) : (outside > 0 ? 0.0 : 1.0);
  return {s.u, s.v, fade};
}

// What a pixel gathers when all `samples` of its march see the sky: Σ_{i<n} weight·decayⁱ.
inline double open_sky_shafts(int samples, double weight, double decay) {
  if (decay == 1) return weight * samples;
  return weight * (1 - std::pow(decay, samples)) / (1 - decay);
}

}  // namespace volgraph::physics
