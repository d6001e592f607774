// Translucent and refracting surfaces (Real-Time Rendering 4th ed., §14.5): Fresnel
// reflectance, the refraction vector, and the colour absorbed through a thickness. CPU
// twin of shaders/include/translucency.glsl: change both together. Templates on the real
// type so tests can check float (what the GPU computes) and the reference can use double.
// Conventions: `to_incident` is the unit vector from the surface point back toward where
// the light (or the view ray) comes from, `normal` the unit normal on its side
// (dot(to_incident, normal) ≥ 0); `eta` the relative index n₁/n₂ (incident side over
// transmitted side).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace volgraph::physics {

template <typename Real>
using Vec3Of = std::array<Real, 3>;

// The level of a mip chain of what lies behind whose texels span the cone a rough interface
// spreads the refracted rays into (HDRP's and Frostbite's rough refraction): α = roughness²,
// turned by 1 − 1/η, over the path behind, seen at `pixel_angle` rad a pixel; log2 of the
// footprint's width in pixels, in [0, 16] (16: past any chain). Twin of shaders/include/translucency.glsl's.
template <typename Real>
Real refraction_blur_lod(Real roughness, Real ior, Real path_behind, Real distance_behind, Real pixel_angle) {
  const Real width = Real(2) * roughness * roughness * (Real(1) - Real(1) / std::max(ior, Real(1))) * std::max(path_behind, Real(0));
  if (!(width > 0) || !(distance_behind > 0) || !(pixel_angle > 0)) return Real(0);
  return std::clamp(std::log2(width / (distance_behind * pixel_angle)), Real(0), Real(16));
}

// The level of an environment cube's mip chain whose texels span a lobe `spread` rad wide,
// level 0's faces `face_size` texels (a texel ~(π/2)/face_size): log2 of the ratio in [0, 16],
// 0 for a sharp lobe. Twin of shaders/include/translucency.glsl's.
template <typename Real>
Real environment_lod(Real spread, int face_size) {
  const Real texel = Real(1.5707963) / Real(std::max(face_size, 1));
  if (!(spread > texel)) return Real(0);
  return std::min(std::log2(spread / texel), Real(16));
}

// Reflectance at normal incidence between media of indices n1 and n2: ((n1 − n2)/(n1 + n2))²
// (RTR4 eq. 9.17; 0.04 for air and glass, n = 1.5).
template <typename Real>
Real fresnel_f0(Real n1, Real n2) {
  const Real r = (n1 - n2) / (n1 + n2);
  return r * r;
}

// Schlick's approximation: F = F0 + (1 − F0)(1 − cos θ)⁵ (RTR4 eq. 9.16), cos θ clamped to [0, 1].
template <typename Real>
Real fresnel_schlick(Real f0, Real cos_theta) {
  const Real m = Real(1) - std::clamp(cos_theta, Real(0), Real(1));
  const Real m2 = m * m;
  return f0 + (Real(1) - f0) * m2 * m2 * m;
}

// The refracted direction by Bec's form (RTR4 eq. 14.28–14.29): w = eta (l·n),
// k = √(1 + (w − eta)(w + eta)), t = (w − k) n − eta l; none beyond the critical angle
// (total internal reflection: 1 + (w − eta)(w + eta) < 0). With eta = 1, t = −l exactly
// (taken apart: the form itself would round).
template <typename Real>
std::optional<Vec3Of<Real>> refract_bec(const Vec3Of<Real>& to_incident, const Vec3Of<Real>& normal, Real eta) {
  // No interface: straight on, exactly (the form's w − k rounds to a few ulps, not to 0).
  if (eta == Real(1)) return Vec3Of<Real>{-to_incident[0], -to_incident[1], -to_incident[2]};
  const Real w = eta * (to_incident[0] * normal[0] + to_incident[1] * normal[1] + to_incident[2] * normal[2]);
  const Real radicand = Real(1) + (w - eta) * (w + eta);
  if (radicand < Real(0)) return std::nullopt;
  const Real k = std::sqrt(radicand);
  return Vec3Of<Real>{(w - k) * normal[0] - eta * to_incident[0], (w - k) * normal[1] - eta * to_incident[1],
                      (w - k) * normal[2] - eta * to_incident[2]};
}

// The extinction that leaves transmittance `color` (a channel) after `distance` m:
// σt = −ln(color)/distance (RTR4 eq. 14.23). A colour of 0 is held at 1e-30 (σt finite,
// e^(−σt·distance) = 1e-30): the slab is opaque, and no Inf reaches a pass.
template <typename Real>
Real sigma_t_from_color(Real color, Real distance) {
  return -std::log(std::clamp(color, Real(1e-30), Real(1))) / distance;
}

// Beer–Lambert through a slab `thickness` m thick along a ray at cosine `cos_transmitted`
// to its normal inside: e^(−σt·thickness / cos) — the longer path at an angle. A grazing
// ray (cos → 0) transmits nothing.
template <typename Real>
Real slab_transmittance(Real sigma_t, Real thickness, Real cos_transmitted) {
  const Real c = std::abs(cos_transmitted);
  if (c <= Real(0)) return thickness > Real(0) && sigma_t > Real(0) ? Real(0) : Real(1);
  return std::exp(-sigma_t * thickness / c);
}

// The interface's reflectance seen at `cos_view` from outside: Schlick's F for indices 1
// and `ior`, and none at all without an interface (ior 1, where Schlick's grazing term
// would reflect light at a boundary that is not there).
template <typename Real>
Real interface_reflectance(Real ior, Real cos_view) {
  if (ior == Real(1)) return Real(0);
  return fresnel_schlick(fresnel_f0(Real(1), ior), cos_view);
}

// cos θt inside a medium of index `ior` for a ray arriving from outside (index 1) at
// cos θi (Snell's law: sin θt = sin θi / ior).
template <typename Real>
Real refracted_cosine(Real ior, Real cos_incident) {
  const Real c = std::clamp(std::abs(cos_incident), Real(0), Real(1));
  return std::sqrt(std::max(Real(0), Real(1) - (Real(1) - c * c) / (ior * ior)));
}

// The path through a thin shell `thickness` m thick seen at cos θi: the shell is crossed
// at the refracted angle, thickness / cos θt (RTR4 §14.5.1, after Drobot's thin shells).
template <typename Real>
Real shell_path_length(Real thickness, Real ior, Real cos_incident) {
  const Real c = refracted_cosine(ior, cos_incident);
  return c > Real(0) ? thickness / c : (thickness > Real(0) ? Real(1e30) : Real(0));
}

// The absorption path inside a solid whose straight path along the view ray is
// `path_along_view` m, seen at cos θi: the ray refracts at the entry (Snell; RTR4 §14.5.2)
// and crosses the same slab, thickness h = path_along_view · cos θi, at θt: h / cos θt.
// Exactly `path_along_view` at ior 1 (no interface) or where θt cannot be had (grazing).
template <typename Real>
Real solid_path_length(Real path_along_view, Real ior, Real cos_incident) {
  if (ior == Real(1)) return path_along_view;
  const Real c_t = refracted_cosine(ior, cos_incident);
  return c_t > Real(0) ? path_along_view * std::clamp(std::abs(cos_incident), Real(0), Real(1)) / c_t : path_along_view;
}

// Where a ray leaves a slab it entered at the origin (a flat solid of parallel faces, the
// slab approximation of screen-space refraction): `to_incident` (unit, toward the viewer)
// refracts by Bec's form into an index `ior` (RTR4 eq. 14.28–14.29), crosses the slab's
// thickness h = path_along_view · cos θi along the refracted ray, and leaves parallel to
// where it came from. Returned: the exit point's offset across the view ray, of length
// h sin(θi − θt) / cos θt; exactly 0 at ior 1 (no interface) and at normal incidence.
template <typename Real>
Vec3Of<Real> slab_exit_offset(const Vec3Of<Real>& to_incident, const Vec3Of<Real>& normal, Real ior, Real path_along_view) {
  const Vec3Of<Real> zero{Real(0), Real(0), Real(0)};
  if (ior == Real(1) || path_along_view <= Real(0)) return zero;
  const Real cos_i = to_incident[0] * normal[0] + to_incident[1] * normal[1] + to_incident[2] * normal[2];
  const std::optional<Vec3Of<Real>> r = refract_bec(to_incident, normal, Real(1) / ior);
  if (!r || cos_i <= Real(0)) return zero;
  const Real cos_t = -((*r)[0] * normal[0] + (*r)[1] * normal[1] + (*r)[2] * normal[2]);
  if (cos_t <= Real(0)) return zero;
  const Real inside = path_along_view * cos_i / cos_t;  // h / cos θt
  Vec3Of<Real> exit{(*r)[0] * inside, (*r)[1] * inside, (*r)[2] * inside};
  // Across the view direction v = −to_incident: exit − v (exit · v).
  const Real along = -(exit[0] * to_incident[0] + exit[1] * to_incident[1] + exit[2] * to_incident[2]);
  for (size_t k = 0; k < 3; ++k) exit[k] -= -to_incident[k] * along;
  return exit;
}

// Where a ray leaves a solid taken locally as a sphere (HDRP's sphere refraction model): the
// sphere tangent at the entry whose chord along the view ray is `path_along_view`, so of
// diameter D = path / cos θi (exact for a sphere); the ray refracted in by Bec's form with
// 1/ior crosses it, s = −(t·n) D, and is refracted out at the exit, whose normal points to
// the centre, with eta = ior — mirrored back inside where that is total internal reflection
// (taken as leaving: one bounce, no more). `offset`: the exit point from the entry; straight
// through (offset −to_incident × path, direction −to_incident) at ior 1, head-on or with no path.
template <typename Real>
struct SphereExit {
  Vec3Of<Real> offset;
  Vec3Of<Real> direction;
};

template <typename Real>
SphereExit<Real> sphere_exit(const Vec3Of<Real>& to_incident, const Vec3Of<Real>& normal, Real ior, Real path_along_view) {
  const auto dot3 = [](const Vec3Of<Real>& a, const Vec3Of<Real>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const Vec3Of<Real> view{-to_incident[0], -to_incident[1], -to_incident[2]};
  const Real path = std::max(path_along_view, Real(0));
  const SphereExit<Real> straight{{view[0] * path, view[1] * path, view[2] * path}, view};
  const Real cos_i = dot3(to_incident, normal);
  if (ior == Real(1) || !(path > Real(0)) || !(cos_i > Real(0))) return straight;
  const std::optional<Vec3Of<Real>> in = refract_bec(to_incident, normal, Real(1) / ior);
  if (!in) return straight;
  const Real diameter = path / cos_i;
  const Real s = -dot3(*in, normal) * diameter;
  SphereExit<Real> out;
  Vec3Of<Real> to_centre;  // from the exit point: the entry's centre offset −n D/2, minus the exit's offset
  for (size_t k = 0; k < 3; ++k) {
    out.offset[k] = (*in)[k] * s;
    to_centre[k] = -normal[k] * diameter / Real(2) - out.offset[k];
  }
  const Real length = std::sqrt(dot3(to_centre, to_centre));
  if (!(length > Real(0))) return straight;
  for (Real& c : to_centre) c /= length;
  const Vec3Of<Real> back{-(*in)[0], -(*in)[1], -(*in)[2]};
  const std::optional<Vec3Of<Real>> leaving = refract_bec(back, to_centre, ior);
  if (leaving) {
    out.direction = *leaving;
  } else {  // total internal reflection: r = d − 2 (d·n) n
    const Real d_n = dot3(*in, to_centre);
    for (size_t k = 0; k < 3; ++k) out.direction[k] = (*in)[k] - Real(2) * d_n * to_centre[k];
  }
  return out;
}

// The IOR per colour channel (red, green, blue) of a dispersive medium: KHR_materials_dispersion's
// `dispersion` = 20/V_d spreads it as the extension's sample implementation does,
// halfSpread = (ior − 1)·0.025·dispersion, red ior − halfSpread, green ior, blue ior + halfSpread.
// Dispersion 0 gives the one IOR in all three.
template <typename Real>
Vec3Of<Real> dispersed_iors(Real ior, Real dispersion) {
  const Real half_spread = (ior - Real(1)) * Real(0.025) * dispersion;
  return Vec3Of<Real>{ior - half_spread, ior, ior + half_spread};
}

// What a translucent surface does to a ray, per channel: it adds `radiance` and passes
// `transmittance` of what lies behind it, C = radiance + transmittance ⊙ C_behind (one
// layer of RTR4 §14.5.1's blending; the blending passes compose layers by it).
template <typename Real>
struct SurfaceLayer {
  Vec3Of<Real> radiance{};
  Vec3Of<Real> transmittance{};
};

// What the layer is made of, as a pass or the reference has it at one point.
template <typename Real>
struct LayerInputs {
  Real alpha = 1;                 // coverage
  Real transmission = 0;          // of the light the interface does not reflect
  Vec3Of<Real> albedo{};          // ρ: the diffuse colour, and the tint of what passes
  Vec3Of<Real> emissive{};        // radiance
  Vec3Of<Real> irradiance{};      // E reaching the surface (lights, shadows and ambient)
  Vec3Of<Real> environment{};     // radiance the specular reflection sees
  Real reflectance = 0;           // F where the ray enters (interface_reflectance)
  Vec3Of<Real> path_transmittance{Real(1), Real(1), Real(1)};  // Beer–Lambert inside
};

// glTF 2.0's dielectric layering (its Appendix B fresnel_mix, with KHR_materials_
// transmission's mix of diffuse and transmitted lobes) over coverage α:
//   radiance      = α [F L_env + (1 − F)(1 − t) ρ/π E + emissive]
//   transmittance = (1 − α) + α (1 − F) t ρ T_path.
// One interface per object, as KHR_materials_volume has it (its volume is bounded by the
// surface the ray enters; no second Fresnel factor where it leaves): a thin wall, a shell
// and a solid alike, so AttenuationTest's rows equal its answer-key row.
template <typename Real>
SurfaceLayer<Real> surface_layer(const LayerInputs<Real>& in) {
  SurfaceLayer<Real> out;
  const Real a = std::clamp(in.alpha, Real(0), Real(1)), t = std::clamp(in.transmission, Real(0), Real(1));
  const Real f = std::clamp(in.reflectance, Real(0), Real(1));
  constexpr Real kInvPi = Real(0.318309886183790671537767526745028724);
  for (size_t c = 0; c < 3; ++c) {
    const Real diffuse = (Real(1) - f) * (Real(1) - t) * in.albedo[c] * kInvPi * in.irradiance[c];
    out.radiance[c] = a * (f * in.environment[c] + diffuse + in.emissive[c]);
    out.transmittance[c] = (Real(1) - a) + a * (Real(1) - f) * t * in.albedo[c] * in.path_transmittance[c];
  }
  return out;
}

// A layer seen through media between the camera and it (their in-scattered radiance S
// and transmittance T up to the layer), composed so that its transmittance can multiply
// what lies behind already fogged over the whole ray: with C_fogged = S(0, d_o) +
// T(0, d_o) C, S(0, d_o) = S + T S(d, d_o) and T(0, d_o) = T T(d, d_o), the exact
//   S + T [radiance + transmittance ⊙ (S(d, d_o) + T(d, d_o) C)]
// is radiance' + transmittance ⊙ C_fogged with radiance' = T radiance + (1 − transmittance) S.
template <typename Real>
SurfaceLayer<Real> fogged_layer(const SurfaceLayer<Real>& layer, const Vec3Of<Real>& in_scattered, const Vec3Of<Real>& media_transmittance) {
  SurfaceLayer<Real> out = layer;
  for (size_t c = 0; c < 3; ++c) {
    out.radiance[c] = media_transmittance[c] * layer.radiance[c] + (Real(1) - layer.transmittance[c]) * in_scattered[c];
  }
  return out;
}

// −ln T of one channel, T held at ≥ 1e-4 (an optical depth of at most 9.2 a layer: a sum
// of 64 stays far inside half float's range). Weighted blended OIT adds these: their sum's
// e^− is the layers' transmittances multiplied, in any order.
template <typename Real>
Real transmittance_depth(Real transmittance) {
  return -std::log(std::max(transmittance, Real(1e-4)));
}

// McGuire & Bavoil 2013's weight for a layer at view depth `depth` m of opacity `opacity`
// (their weight for a wide depth range), clamped to [1e-2, 3e3]; then held so one layer
// of radiance `peak` adds at most 2⁻⁶ of half float's largest value (65504) to the
// accumulation: 64 such layers cannot overflow it.
template <typename Real>
Real oit_weight(Real depth, Real opacity, Real peak) {
  const Real z = std::abs(depth);
  const Real z5 = z / Real(5), z200 = z / Real(200);
  const Real z200_3 = z200 * z200 * z200;
  const Real w = std::clamp(Real(10) / (Real(1e-5) + z5 * z5 + z200_3 * z200_3), Real(1e-2), Real(3e3));
  const Real budget = Real(65504) / Real(64);
  return std::clamp(opacity, Real(0), Real(1)) * std::min(w, budget / std::max(peak, Real(1)));
}

}  // namespace volgraph::physics
