// Translucent and refracting surfaces (Real-Time Rendering 4th ed., §14.5): Fresnel
// reflectance, the refraction vector, the colour absorbed through a thickness. CPU twin:
// physics/translucency.h (its conventions: `to_incident` from the surface back toward the
// incoming ray, `normal` on its side, `eta` = n₁/n₂) — change both together.
#ifndef VOLGRAPH_TRANSLUCENCY_GLSL
#define VOLGRAPH_TRANSLUCENCY_GLSL

// ((n1 − n2)/(n1 + n2))² (RTR4 eq. 9.17).
float fresnel_f0(float n1, float n2) {
  const float r = (n1 - n2) / (n1 + n2);
  return r * r;
}

// F0 + (1 − F0)(1 − cos θ)⁵ (RTR4 eq. 9.16).
float fresnel_schlick(float f0, float cos_theta) {
  const float m = 1.0 - clamp(cos_theta, 0.0, 1.0);
  const float m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

// Bec's refraction (RTR4 eq. 14.28–14.29); false beyond the critical angle (total
// internal reflection), `transmitted` then left as it was.
bool refract_bec(vec3 to_incident, vec3 normal, float eta, out vec3 transmitted) {
  if (eta == 1.0) {  // no interface: straight on, exactly
    transmitted = -to_incident;
    return true;
  }
  const float w = eta * dot(to_incident, normal);
  const float radicand = 1.0 + (w - eta) * (w + eta);
  transmitted = vec3(0.0);
  if (radicand < 0.0) return false;
  transmitted = (w - sqrt(radicand)) * normal - eta * to_incident;
  return true;
}

// σt = −ln(colour)/distance (RTR4 eq. 14.23), a colour of 0 held at 1e-30.
vec3 sigma_t_from_color(vec3 color, float distance) { return -log(clamp(color, vec3(1e-30), vec3(1.0))) / distance; }

// e^(−σt·thickness / |cos|); a grazing ray transmits nothing.
vec3 slab_transmittance(vec3 sigma_t, float thickness, float cos_transmitted) {
  const float c = abs(cos_transmitted);
  if (c <= 0.0) return (thickness > 0.0) ? vec3(equal(sigma_t, vec3(0.0))) : vec3(1.0);
  return exp(-sigma_t * thickness / c);
}

#endif
