// Brute-force multiple scattering in the cloud layer (docs/clouds.md "Multiple scattering
// against brute force"): the radiance the layer sends along a camera ray, by a Monte Carlo
// random walk, against which Wrenninge et al. 2013's octaves (cloud_lighting.h) are measured.
// - Free flights by delta (Woodcock) tracking against a majorant σ̄ ≥ σt everywhere
//   (Woodcock et al. 1965; Novák et al. 2018 §3): for the layer σ̄ = extinction × coverage,
//   since cloud_base_density is (remapped base in [0, 1]) × coverage and erosion only lowers it.
// - Albedo 1 (σs = σt, as cloud_density.h): every real collision scatters, the path's weight
//   stays 1; the direction by the SAME dual-lobe HG as cloud_phase, sampled exactly (the back
//   lobe with probability back_weight, then HG's inverse CDF).
// - Next-event estimation toward the sun at every collision, E_sun · p(θ) · T_sun, T_sun by
//   ratio tracking to where the layer ends (Novák et al. 2014), none where the ground hides
//   the sun; the ambient as CloudReference takes it, σs · L_ambient at the first collision.
// - Up to `bounces` collisions; nothing is reflected by the ground, a path that leaves the
//   layer is lost (the reference's layer has no ground bounce and no second entry).
// Deterministic: each estimate is seeded by its caller (cloud_pixel_seed), so reruns agree.
#pragma once

#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"
#include "reference/clouds.h"
#include "reference/random.h"

namespace volgraph::reference {

// What the walk needs from a medium: σt at a point, a majorant, and how far a ray from a
// point inside goes before it leaves. CloudLayerMedium is the layer; tests build slabs.
class CloudWalkMedium {
 public:
  virtual ~CloudWalkMedium() = default;
  virtual double sigma_t(const Vec3& p) const = 0;
  // σ̄ ≥ sigma_t everywhere (delta and ratio tracking are unbiased only then).
  virtual double majorant() const = 0;
  // The distance from p (inside) along unit d to where the medium ends.
  virtual double exit_distance(const Vec3& p, const Vec3& d) const = 0;
  // True where the ground hides the sun from p.
  virtual bool ground_hides_sun(const Vec3& p) const = 0;
};

// The sun, the ambient and the phase the walk lights the medium with.
struct CloudWalkLight {
  bool has_sun = false;
  Vec3 to_sun{0, 1, 0}, sun_irradiance{0, 0, 0};
  Vec3 ambient{0, 0, 0};  // W/(m²·sr), isotropic, at the first collision
  double g_forward = 0.8, g_back = -0.3, back_weight = 0.2;
};

// CloudReference's layer as a walk medium (its density, spheres and ground test).
class CloudLayerMedium final : public CloudWalkMedium {
 public:
  explicit CloudLayerMedium(const CloudReference& clouds) : clouds_(clouds) {}
  double sigma_t(const Vec3& p) const override;
  double majorant() const override;
  double exit_distance(const Vec3& p, const Vec3& d) const override;
  bool ground_hides_sun(const Vec3& p) const override { return clouds_.ground_hides_sun(p); }

 private:
  const CloudReference& clouds_;
};

// The reference's sun, ambient and cloud_march phase parameters.
CloudWalkLight cloud_walk_light(const CloudReference& clouds);

// The walk's random numbers: a Random seeded through splitmix64, so nearby seeds (pixels)
// give unrelated streams.
class CloudRandom : public Random {
 public:
  explicit CloudRandom(uint64_t seed) : Random(splitmix64(seed)) {}
};

// A scattered direction about the walk's unit direction d, drawn from the dual-lobe phase
// exactly as cloud_phase mixes it (the back lobe with probability back_weight, then HG's
// inverse CDF).
Vec3 sample_cloud_phase(const CloudWalkLight& light, const Vec3& d, CloudRandom& random);

// One path's radiance, and the part each scattering order brought (order k at index k − 1).
struct CloudPath {
  Vec3 radiance{0, 0, 0};
  std::vector<double> by_order;  // the sun's and ambient's scalar weight per order (× irradiance for radiance)
};

// One random walk from `origin` along unit `d`, entering the medium at t_in and leaving it at
// t_out along that first ray, for up to `bounces` collisions.
CloudPath trace_cloud_path(const CloudWalkMedium& medium, const CloudWalkLight& light, const Vec3& origin, const Vec3& d,
                           double t_in, double t_out, int bounces, CloudRandom& random);

struct CloudPathSettings {
  int bounces = 256;   // collisions per path at most
  int samples = 256;   // paths per estimate
};

// Radiance along a camera ray, its standard error (per channel, √(var / n)) and the mean
// radiance each scattering order brought (the sun's part, per unit irradiance).
struct CloudRadianceEstimate {
  Vec3 radiance{0, 0, 0}, standard_error{0, 0, 0};
  std::vector<double> by_order;
};

// The layer's multiply scattered radiance along the camera ray of unit `direction`, up to
// `surface` metres (the opaque surface; infinity where none), the first entry into the layer
// as CloudReference::along (clipped by max_distance). Deterministic in `seed`.
CloudRadianceEstimate cloud_multiple_scattering(const CloudReference& clouds, const Vec3& direction, double surface,
                                                const CloudPathSettings& settings, uint64_t seed);

// A seed per pixel (i, j) of a frame, from a base seed.
uint64_t cloud_pixel_seed(uint32_t i, uint32_t j, uint64_t base = 0);

}  // namespace volgraph::reference
