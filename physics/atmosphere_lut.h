// The atmosphere's lookup-table parametrisations, shared by the LUT passes and the CPU
// reference: a texture coordinate (u, v) in [0, 1]² ↔ the physical parameters a texel
// holds. CPU twin of shaders/include/atmosphere_lut.glsl — change both together.
// - Transmittance (Bruneton 2017, GetTransmittanceTextureUvFromRMu and its inverse): (r, mu)
//   for rays that do not hit the ground, through the non-linear x_mu (the distance to the
//   top between its extremes) and x_r (ρ / H, the distance to the horizon over its
//   largest).
// - Multiple scattering (Hillaire 2020, GetMultipleScattering): the sun's zenith
//   cosine mu_s and the altitude, both linear.
// - Sky view (Hillaire 2020, SkyViewLutParamsToUv): latitude around the camera with a
//   quadratic mapping either side of the horizon (v = 1/2) that keeps the horizon sharp,
//   and the cosine of the azimuth from the sun, through a square root (u = 0 toward the sun).
// Every unit coordinate x ∈ [0, 1] is mapped to the texel centres' range by Bruneton 2017's
// GetTextureCoordFromUnitRange (0.5/n + x(1 − 1/n)), whose inverse is exact: texel i's
// centre holds x = i/(n − 1). (Hillaire 2020's fromUnitToSubUvs / fromSubUvsToUnit are not
// each other's inverse; one exact pair is used for every LUT here.)
#pragma once

#include "graph/scene/scene.h"

namespace volgraph::physics {

struct LutUv {
  double u = 0, v = 0;
};

// Bruneton 2017, GetTextureCoordFromUnitRange / GetUnitRangeFromTextureCoord.
double texture_coord_from_unit_range(double x, int texture_size);
double unit_range_from_texture_coord(double u, int texture_size);

// Bruneton 2017's transmittance texture (default 256 × 64). r in [bottom, top], mu at or
// above the horizon.
struct TransmittanceLutSize {
  int width = 256, height = 64;
};
struct RadiusAndMu {
  double r = 0, mu = 0;
};
LutUv transmittance_lut_uv(const Atmosphere& atmosphere, double r, double mu, TransmittanceLutSize size = {});
RadiusAndMu transmittance_lut_r_mu(const Atmosphere& atmosphere, LutUv uv, TransmittanceLutSize size = {});

// Hillaire 2020's multiple-scattering LUT (default 32 × 32): u the sun's zenith cosine
// (mu_s · 0.5 + 0.5), v the altitude over the atmosphere's thickness.
struct MultiscatteringLutSize {
  int width = 32, height = 32;
};
struct RadiusAndMuS {
  double r = 0, mu_s = 0;
};
LutUv multiscattering_lut_uv(const Atmosphere& atmosphere, double r, double mu_s, MultiscatteringLutSize size = {});
RadiusAndMuS multiscattering_lut_r_mu_s(const Atmosphere& atmosphere, LutUv uv, MultiscatteringLutSize size = {});

// Hillaire 2020's sky-view LUT (default 192 × 108) for a camera at r (bottom ≤ r ≤ top): a
// view direction's zenith cosine mu and cos_azimuth, the cosine of the angle between the
// view's and the sun's directions projected on the horizontal plane.
struct SkyViewLutSize {
  int width = 192, height = 108;
};
struct SkyViewDirection {
  double mu = 0, cos_azimuth = 0;
};
LutUv sky_view_lut_uv(const Atmosphere& atmosphere, double r, SkyViewDirection direction, SkyViewLutSize size = {});
SkyViewDirection sky_view_lut_direction(const Atmosphere& atmosphere, double r, LutUv uv, SkyViewLutSize size = {});

// Aerial perspective (Hillaire 2020 §5.4): a camera-frustum volume of `slices` slices over
// `distance` m along each ray, slice k's texel holding the air from the camera to (k + ½)
// of a slice. A point `t` m along its ray reads at w = t / distance (texture coordinate;
// clamped to the texel centres), and in front of the first texel's centre the values
// ramp linearly from the camera's (no scattering, full transmittance): ramp = t / (½ slice).
struct AerialSlice {
  double w = 0;     // the volume's third texture coordinate
  double ramp = 1;  // how much of the first texel's value reaches it (1 past its centre)
};
AerialSlice aerial_perspective_slice(double t, double distance, int slices);

}  // namespace volgraph::physics
