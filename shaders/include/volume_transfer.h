// The 1D transfer function of volume_visualize (RTR4 14.3.1): density → colour and opacity,
// piecewise linear between a small table's knots, and the opacity of a step of another
// length than the table's. ONE TEXT FOR BOTH SIDES: GLSL includes this file, C++ includes it
// inside a namespace with GLM's types (physics/volume_transfer.h).
#ifndef VOLGRAPH_VOLUME_TRANSFER_H
#define VOLGRAPH_VOLUME_TRANSFER_H

#include "volume_fn.h"

// The table's most knots.
#define VOLUME_TRANSFER_MAX_KNOTS 8

// The table at `density`: knot i at density knot_density[i].x (ascending; two knots at one
// density make a step) with colour and opacity knot_rgba[i]; linear between neighbours,
// the end knots' values outside them. At a knot's density the knot's value exactly (the
// segment starting there, at fraction 0). `count` is clamped to [1, VOLUME_TRANSFER_MAX_KNOTS].
VOLUME_FN vec4 volume_transfer_lookup(const vec4 knot_density[VOLUME_TRANSFER_MAX_KNOTS],
                                      const vec4 knot_rgba[VOLUME_TRANSFER_MAX_KNOTS], int count, float density) {
  const int n = clamp(count, 1, VOLUME_TRANSFER_MAX_KNOTS);
  if (!(density > knot_density[0].x)) return knot_rgba[0];  // below the first knot, or NaN
  for (int i = 1; i < n; ++i) {
    if (density < knot_density[i].x) {
      const float low = knot_density[i - 1].x;
      const float f = (density - low) / (knot_density[i].x - low);  // low ≤ density < high: no division by 0
      return mix(knot_rgba[i - 1], knot_rgba[i], f);
    }
  }
  return knot_rgba[n - 1];
}

// A 2D transfer function of density and gradient magnitude (Kniss, Kindlmann & Hansen 2002),
// separable here: the 1D table's colour and opacity (`from_table`), the opacity times a ramp in
// the gradient's magnitude |∇ρ| (per metre) from 0 at `gradient_low` to 1 at `gradient_high` —
// uniform regions vanish, the boundaries between materials show. gradient_high ≤ 0: the table's.
VOLUME_FN vec4 volume_transfer_2d(vec4 from_table, float gradient_magnitude, float gradient_low, float gradient_high) {
  if (!(gradient_high > 0.0f)) return from_table;
  if (!(gradient_magnitude > gradient_low)) return vec4(from_table.x, from_table.y, from_table.z, 0.0f);  // NaN too
  const float ramp = min((gradient_magnitude - gradient_low) / max(gradient_high - gradient_low, 1e-20f), 1.0f);
  return vec4(from_table.x, from_table.y, from_table.z, from_table.w * ramp);
}

// A full 2D transfer table (Kniss, Kindlmann & Hansen 2002): texel (i, j) of a W × H table holds
// the colour and opacity at density i/(W − 1) and gradient magnitude j/(H − 1)·gradient_max
// (1/m). The texel position of (density, |∇ρ|), both clamped to the table; bilinear between
// texels, so a lookup at a table's sample reads that texel alone (fraction 0) and equals it
// exactly (when i/(W − 1)·(W − 1) is i in float: W − 1 a power of two, or density 0 or 1).
VOLUME_FN vec2 volume_transfer_table_position(float density, float gradient_magnitude, float gradient_max, vec2 size) {
  const float d = density > 0.0f ? min(density, 1.0f) : 0.0f;  // NaN → 0
  const float g = gradient_max > 0.0f && gradient_magnitude > 0.0f ? min(gradient_magnitude / gradient_max, 1.0f) : 0.0f;
  return vec2(d * (size.x - 1.0f), g * (size.y - 1.0f));
}

// Bilinear between the four texels around a position: t00 at its floor, t10 one texel on in
// x, t01 one on in y; `fraction` the position minus its floor. Fraction 0: t00 exactly.
VOLUME_FN vec4 volume_transfer_table_mix(vec4 t00, vec4 t10, vec4 t01, vec4 t11, vec2 fraction) {
  return mix(mix(t00, t10, fraction.x), mix(t01, t11, fraction.x), fraction.y);
}

// The opacity of a step of length `step` when the table's opacity α holds for steps of
// `reference_step` (Engel et al. 2006, Real-Time Volume Graphics, eq. 7.1; RTR4 14.3.1):
// α' = 1 − (1 − α)^(Δ/Δ₀). 0 for an empty step, 1 for α = 1.
VOLUME_FN float volume_step_opacity(float alpha, float step, float reference_step) {
  const float a = clamp(alpha, 0.0f, 1.0f);
  if (!(step > 0.0f) || !(reference_step > 0.0f)) return 0.0f;
  if (a >= 1.0f) return 1.0f;
  return 1.0f - exp(log(1.0f - a) * (step / reference_step));
}

#endif  // VOLGRAPH_VOLUME_TRANSFER_H
