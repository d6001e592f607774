// Single scattering of a point light along a ray through a homogeneous medium, without
// shadows: the airlight of Sun, Ramamoorthi, Narasimhan, Nayar 2005 (§3). CPU twin:
// physics/airlight.h — change both together; the derivation, the quadrature and
// its measured error are documented there.
#ifndef VOLGRAPH_AIRLIGHT_GLSL
#define VOLGRAPH_AIRLIGHT_GLSL
#include "phase.glsl"

const float AIRLIGHT_MIN_DISTANCE = 1e-4;  // m: h is clamped here (the integral grows like 1/h)
const int AIRLIGHT_PANELS = 8;
const float AIRLIGHT_CUTOFF = 40.0;
const float GAUSS_LEGENDRE_8_NODES[4] = float[4](0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363);
const float GAUSS_LEGENDRE_8_WEIGHTS[4] = float[4](0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763);

struct AirlightGeometry {
  float t_c;  // the light's projection on the ray (m)
  float h;    // its distance from the ray's line (m), at least AIRLIGHT_MIN_DISTANCE
};

AirlightGeometry airlight_geometry(vec3 origin, vec3 direction, vec3 light) {
  const vec3 to_light = light - origin;
  const float t_c = dot(to_light, direction);
  return AirlightGeometry(t_c, max(length(to_light - t_c * direction), AIRLIGHT_MIN_DISTANCE));
}

// ∫₀^len dt / (4π d(t)²) (Sun et al. 2005, σt → 0): (atan((len − t_c)/h) + atan(t_c/h)) / (4π h),
// the angle evaluated as one atan2 (no cancellation).
float airlight_no_extinction(AirlightGeometry g, float len) {
  return atan(g.h * len, g.h * g.h + g.t_c * (g.t_c - len)) * INV_FOUR_PI / g.h;
}

// Where the integrand has fallen below e^(−AIRLIGHT_CUTOFF) of its value at the camera.
float airlight_negligible_beyond(AirlightGeometry g, float sigma_t) {
  if (!(sigma_t > 0.0)) return 3.0e38;
  const float margin = AIRLIGHT_CUTOFF / sigma_t;
  const float at_camera = sqrt(g.h * g.h + g.t_c * g.t_c);
  return margin * (2.0 * at_camera + margin) / (2.0 * (at_camera - g.t_c + margin));
}

float airlight_asinh(float x) {
  const float a = min(abs(x), 1e15);
  return sign(x) * log(a + sqrt(a * a + 1.0));
}

// ∫₀^len p_HG(g, cos θ) · e^(−σt·(t + d)) / d² dt, per channel of σt, by composite
// Gauss–Legendre in w (t − t_c = h·sinh w).
vec3 airlight(AirlightGeometry geometry, float len, vec3 sigma_t, float g) {
  const float h = geometry.h, t_c = geometry.t_c;
  const float least_sigma_t = min(sigma_t.r, min(sigma_t.g, sigma_t.b));
  const float end = min(len, airlight_negligible_beyond(geometry, least_sigma_t));
  const float w0 = airlight_asinh(-t_c / h), w1 = airlight_asinh((end - t_c) / h);
  const float panel = (w1 - w0) / float(AIRLIGHT_PANELS);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < AIRLIGHT_PANELS; ++k) {
    const float centre = w0 + (float(k) + 0.5) * panel;
    for (int n = 0; n < 8; ++n) {
      const float x = (n < 4 ? -1.0 : 1.0) * GAUSS_LEGENDRE_8_NODES[n % 4];
      const float w = centre + 0.5 * panel * x;
      const float along = h * sinh(w), distance = h * cosh(w);
      const float t = max(t_c + along, 0.0);
      const vec3 attenuation = exp(-min(sigma_t * (t + distance), vec3(80.0)));
      sum += GAUSS_LEGENDRE_8_WEIGHTS[n % 4] * phase_hg(g, -along / distance) * attenuation / distance;
    }
  }
  return sum * 0.5 * panel;
}

#endif
