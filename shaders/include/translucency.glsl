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

// Schlick's F for indices 1 and ior; 0 without an interface (ior 1).
float interface_reflectance(float ior, float cos_view) {
  if (ior == 1.0) return 0.0;
  return fresnel_schlick(fresnel_f0(1.0, ior), cos_view);
}

// cos θt inside (index ior) for a ray from outside at cos θi (Snell's law).
float refracted_cosine(float ior, float cos_incident) {
  const float c = clamp(abs(cos_incident), 0.0, 1.0);
  return sqrt(max(0.0, 1.0 - (1.0 - c * c) / (ior * ior)));
}

// A thin shell crossed at the refracted angle: thickness / cos θt (RTR4 §14.5.1, Drobot).
float shell_path_length(float thickness, float ior, float cos_incident) {
  const float c = refracted_cosine(ior, cos_incident);
  return c > 0.0 ? thickness / c : (thickness > 0.0 ? 1e30 : 0.0);
}

// A solid's absorption path: its straight path along the view ray as the same slab crossed
// at the refracted angle, path · cos θi / cos θt (Snell; RTR4 §14.5.2); as is at ior 1.
float solid_path_length(float path_along_view, float ior, float cos_incident) {
  if (ior == 1.0) return path_along_view;
  const float c_t = refracted_cosine(ior, cos_incident);
  return c_t > 0.0 ? path_along_view * clamp(abs(cos_incident), 0.0, 1.0) / c_t : path_along_view;
}

// Where a ray leaves a slab it entered at the origin, across the view ray (physics::
// slab_exit_offset): h sin(θi − θt) / cos θt, h = path_along_view · cos θi; 0 at ior 1.
vec3 slab_exit_offset(vec3 to_incident, vec3 normal, float ior, float path_along_view) {
  if (ior == 1.0 || path_along_view <= 0.0) return vec3(0.0);
  const float cos_i = dot(to_incident, normal);
  vec3 r;
  if (!refract_bec(to_incident, normal, 1.0 / ior, r) || cos_i <= 0.0) return vec3(0.0);
  const float cos_t = -dot(r, normal);
  if (cos_t <= 0.0) return vec3(0.0);
  const vec3 exit_point = r * (path_along_view * cos_i / cos_t);
  return exit_point + to_incident * -dot(exit_point, to_incident);
}

// Where a ray leaves a solid taken locally as a sphere (HDRP's sphere refraction model): the
// sphere tangent at the entry whose chord along the view ray is `path_along_view` (diameter
// path / cos θi: exact for a sphere), crossed by the ray Bec refracts in (1/ior) and
// refracted out at the exit (eta = ior; mirrored back inside at total internal reflection).
// physics::sphere_exit.
struct SphereExit {
  vec3 offset;     // the exit point from the entry
  vec3 direction;  // unit, leaving
};
SphereExit sphere_exit(vec3 to_incident, vec3 normal, float ior, float path_along_view) {
  const float path = max(path_along_view, 0.0);
  const SphereExit straight = SphereExit(-to_incident * path, -to_incident);
  const float cos_i = dot(to_incident, normal);
  vec3 inward;
  if (ior == 1.0 || !(path > 0.0) || !(cos_i > 0.0) || !refract_bec(to_incident, normal, 1.0 / ior, inward)) return straight;
  const float diameter = path / cos_i;
  SphereExit leaving;
  leaving.offset = inward * (-dot(inward, normal) * diameter);
  const vec3 to_centre_unnormalised = -normal * (diameter * 0.5) - leaving.offset;
  const float to_centre_length = length(to_centre_unnormalised);
  if (!(to_centre_length > 0.0)) return straight;
  const vec3 to_centre = to_centre_unnormalised / to_centre_length;
  if (!refract_bec(-inward, to_centre, ior, leaving.direction)) leaving.direction = inward - 2.0 * dot(inward, to_centre) * to_centre;
  return leaving;
}

// The level of a mip chain of what lies behind (generate_mips) whose texels span the cone a
// rough interface spreads the refracted rays into (HDRP's and Frostbite's rough refraction:
// cone width → level): GGX's lobe half-width α = roughness² (in slope) turned by 1 − 1/η
// through the interface (the refracted ray's deviation per unit tilt of the normal, head-on),
// over the path from the interface to the surface behind, seen from the camera at
// `pixel_angle` rad a pixel: log2 of the footprint's width in pixels, in [0, 16] — 0 for a
// smooth interface, at IOR 1, or with nothing behind. physics::refraction_blur_lod.
float refraction_blur_lod(float roughness, float ior, float path_behind, float distance_behind, float pixel_angle) {
  const float width = 2.0 * roughness * roughness * (1.0 - 1.0 / max(ior, 1.0)) * max(path_behind, 0.0);
  if (!(width > 0.0) || !(distance_behind > 0.0) || !(pixel_angle > 0.0)) return 0.0;
  return clamp(log2(width / (distance_behind * pixel_angle)), 0.0, 16.0);  // 16: past any chain (finite for any input)
}

// The level of an environment cube's mip chain (cube_mips) whose texels span a lobe
// `spread` rad wide, on a cube whose level 0 faces are `face_size` texels (a texel spans
// ~(π/2)/face_size there): log2 of the ratio, in [0, 16]; 0 for a sharp lobe. The spread of
// a rough interface's lobe: 2α (α = roughness², GGX's slope width) for the reflection, turned by
// 1 − 1/η for the refraction, as refraction_blur_lod. physics::environment_lod.
float environment_lod(float spread, int face_size) {
  const float texel = 1.5707963 / float(max(face_size, 1));
  if (!(spread > texel)) return 0.0;
  return min(log2(spread / texel), 16.0);
}

// C = radiance + transmittance ⊙ C_behind, per channel.
struct SurfaceLayer {
  vec3 radiance;
  vec3 transmittance;
};

struct LayerInputs {
  float alpha;
  float transmission;
  vec3 albedo;
  vec3 emissive;
  vec3 irradiance;
  vec3 environment;
  float reflectance;
  vec3 path_transmittance;
};

// glTF 2.0's dielectric layering over coverage α:
//   radiance = α [F L_env + (1 − F)(1 − t) ρ/π E + emissive],
//   transmittance = (1 − α) + α (1 − F) t ρ T_path: one interface per object
// (KHR_materials_volume; physics::surface_layer says why).
SurfaceLayer surface_layer(LayerInputs l) {
  const float a = clamp(l.alpha, 0.0, 1.0), t = clamp(l.transmission, 0.0, 1.0);
  const float f = clamp(l.reflectance, 0.0, 1.0);
  const vec3 diffuse = (1.0 - f) * (1.0 - t) * l.albedo * 0.318309886 * l.irradiance;
  SurfaceLayer s;
  s.radiance = a * (f * l.environment + diffuse + l.emissive);
  s.transmittance = vec3(1.0 - a) + a * (1.0 - f) * t * l.albedo * l.path_transmittance;
  return s;
}

// The layer seen through media of in-scattered S and transmittance T in front of it:
// radiance' = T radiance + (1 − transmittance) S (physics::fogged_layer derives it).
SurfaceLayer fogged_layer(SurfaceLayer layer, vec3 in_scattered, vec3 media_transmittance) {
  layer.radiance = media_transmittance * layer.radiance + (vec3(1.0) - layer.transmittance) * in_scattered;
  return layer;
}

// −ln T per channel, T held at ≥ 1e-4 (an optical depth of at most 9.2 a layer: a sum of
// 64 stays far inside half float's range, and e^−9.2 is black to an 8-bit image).
vec3 transmittance_depth(vec3 transmittance) { return -log(max(transmittance, vec3(1e-4))); }

// McGuire & Bavoil 2013's wide-range depth weight, clamped to [1e-2, 3e3] and held so one
// layer of radiance `peak` adds at most 65504/64 to a half-float accumulation.
float oit_weight(float depth, float opacity, float peak) {
  const float z = abs(depth);
  const float z5 = z / 5.0, z200 = z / 200.0;
  const float z200_3 = z200 * z200 * z200;
  const float w = clamp(10.0 / (1e-5 + z5 * z5 + z200_3 * z200_3), 1e-2, 3e3);
  return clamp(opacity, 0.0, 1.0) * min(w, (65504.0 / 64.0) / max(peak, 1.0));
}

#endif
