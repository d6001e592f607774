// The scene's participating media as the reference renderer sees them (DESIGN.md units,
// σ in 1/m): the global homogeneous fog, the exponential height fog (every coefficient
// of its medium, emission included, scaled by e^(−falloff·(y − base_height))), and the
// homogeneous volumes — a box of edges `size`, a sphere of radius size[0], an ellipsoid
// of radii `size`, centred at the origin and carried into the world by the transform.
// Volumes with noise (heterogeneous density) are not supported yet: see unsupported().
// Media that overlap add their coefficients. Emission is a source
// term, radiance added per metre of path (W/(m²·sr·m)), attenuated like in-scattering.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "graph/scene/scene.h"
#include "passes/shading/camera.h"

namespace volgraph::reference {

// A parameter interval [enter, exit] of a ray, enter ≤ exit.
struct Interval {
  double enter = 0, exit = 0;
};

// Where the ray origin + t·direction is inside the unit shape of `shape` (box: edges 1;
// sphere, ellipsoid: radius 1), in that shape's space: analytic slabs or quadric (a
// volume's size scales the unit shape before its transform).
std::optional<Interval> unit_shape_interval(Shape shape, const Vec3& origin, const Vec3& direction);

// Beer–Lambert per channel: e^(−τ) of an optical depth τ.
Vec3 transmittance_of(const Vec3& optical_depth);

// What the media scatter toward the viewer at a point, summed over overlapping media.
struct MediumPoint {
  Vec3 sigma_s{0, 0, 0};
  Vec3 sigma_t{0, 0, 0};
  Vec3 emission{0, 0, 0};
};

// Why the reference cannot render these media ("" when it can).
std::string unsupported(const Media& media);

class SceneMedia {
 public:
  explicit SceneMedia(const Media& media);

  bool empty() const { return !fog_ && !height_fog_ && volumes_.empty(); }

  MediumPoint at(const Vec3& p) const;
  // Σ over media of σs·p(cos θ) (Henyey–Greenstein with the medium's g; isotropic when
  // g = 0) per channel; cos θ between the light's direction of travel and the direction
  // scattered toward the viewer.
  Vec3 scattering(const Vec3& p, double cos_theta) const;

  // The parameters in (t0, t1) where origin + t·direction enters or leaves a volume,
  // ascending: between two of them the set of media is the same.
  std::vector<double> boundaries(const Vec3& origin, const Vec3& direction, double t0, double t1) const;

  // ∫ σt along origin + t·direction (unit), t ∈ [t0, t1], per channel, in closed form
  // (Beer–Lambert segments in the volumes, shading/media.h's closed form for height fog).
  Vec3 optical_depth(const Vec3& origin, const Vec3& direction, double t0, double t1) const;
  // The same from t = 0 to infinity, toward a directional light. The global fog is left
  // out: a directional light's irradiance is defined as what reaches the point through it
  // (an unbounded homogeneous medium would extinguish any distant light); the height fog
  // and the volumes count. Infinite (as 1e300) when the ray goes down through height fog.
  Vec3 optical_depth_to_infinity(const Vec3& origin, const Vec3& direction) const;

 private:
  struct Volume {
    Shape shape;
    shading::Mat4 model;     // local to world
    shading::Mat4 inverse;   // world to local (affine)
    Medium medium;
  };
  // Calls back with every medium at p and its density there (1 but in height fog).
  void visit(const Vec3& p, const std::function<void(const Medium&, double)>& medium_with_density) const;
  std::optional<Interval> volume_interval(const Volume& v, const Vec3& origin, const Vec3& direction) const;
  Vec3 volumes_optical_depth(const Vec3& origin, const Vec3& direction, double t0, double t1) const;
  Vec3 height_fog_optical_depth(double origin_y, double direction_y, double length) const;

  std::optional<Medium> fog_;
  std::optional<HeightFog> height_fog_;
  std::vector<Volume> volumes_;
};

}  // namespace volgraph::reference
