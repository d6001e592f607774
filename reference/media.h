// The scene's participating media as the reference renderer sees them (DESIGN.md units,
// σ in 1/m). What the media are at a point comes from the shaders' CPU twin,
// physics::MediaField (double): the global homogeneous fog, the exponential height fog
// and the local volumes — a box of edges `size`, a sphere of radius size[0], an
// ellipsoid of radii `size`, centred at the origin and carried into the world by the
// transform — each volume's density its edge fade times its noise (physics/noise.h).
// Media that overlap add their coefficients; emission is a source term, radiance added
// per metre of path (W/(m²·sr·m)), attenuated like in-scattering. What this file adds
// is along rays: where the volumes begin and end, and optical depth — closed form for
// the fog, the height fog and uniform volumes, Gauss–Legendre quadrature of the twin's
// density for volumes with an edge fade or noise (reference/gauss_legendre.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "graph/scene/scene.h"
#include "physics/camera.h"
#include "physics/media_field.h"
#include "physics/shape_interval.h"

namespace volgraph::reference {

// A parameter interval [enter, exit] of a ray, enter ≤ exit; where a ray runs inside a
// volume's unit shape: physics/shape_interval.h.
using Interval = physics::RayInterval;

// Beer–Lambert per channel: e^(−τ) of an optical depth τ.
Vec3 transmittance_of(const Vec3& optical_depth);

// How finely heterogeneous volumes are integrated along a ray.
struct MediaQuadrature {
  // Gauss–Legendre panels per lattice cell of the noise's finest octave (its features'
  // size) and per edge fade length; measured in tests/reference/media_test.cpp.
  double panels_per_noise_cell = 1;
  double panels_per_edge_fade = 4;
  // Camera rays are cut into segments this many per finest noise cell, so that each
  // segment's transmittance is a short quadrature and its in-scattering smooth.
  double segments_per_noise_cell = 1;
};

class SceneMedia {
 public:
  explicit SceneMedia(const Media& media, const MediaQuadrature& quadrature = {});

  bool empty() const;
  // Why the reference under-resolves some noisy volume ("" when it resolves them all): its
  // finest octave has more cells along a ray than a chord's panels (MediaQuadrature).
  std::string under_resolved() const;

  // σs, σa, emission and the σs-weighted g of every medium at p (the twin's sample).
  physics::MediaSample at(const Vec3& p) const { return field_.sample(p); }
  // Σ over media of density·σs·p(cos θ) (Henyey–Greenstein with the medium's g;
  // isotropic when g = 0) per channel; cos θ between the light's direction of travel and
  // the direction scattered toward the viewer.
  Vec3 scattering(const Vec3& p, double cos_theta) const;

  // The parameters in (t0, t1) where origin + t·direction (unit) enters or leaves a
  // volume or the full-density core inside its edge fade, and the cuts through noisy
  // volumes (MediaQuadrature), ascending: between two of them the media change smoothly.
  std::vector<double> boundaries(const Vec3& origin, const Vec3& direction, double t0, double t1) const;

  // The Gauss–Legendre panel length (m) for the part [t0, t1] of the ray where it runs
  // through noisy volumes (the shortest of theirs), 0 where it runs through none: noise
  // is integrated on fixed panels (its coverage clamp puts kinks everywhere, which an
  // adaptive rule would chase one by one).
  double noisy_panel(const Vec3& origin, const Vec3& direction, double t0, double t1) const;

  // ∫ σt along origin + t·direction (unit), t ∈ [t0, t1], per channel.
  Vec3 optical_depth(const Vec3& origin, const Vec3& direction, double t0, double t1) const;
  // The same from t = 0 to infinity, toward a directional light. The global fog is left
  // out: a directional light's irradiance is defined as what reaches the point through it
  // (an unbounded homogeneous medium would extinguish any distant light); the height fog
  // and the volumes count. Infinite (as 1e300) when the ray goes down through height fog.
  Vec3 optical_depth_to_infinity(const Vec3& origin, const Vec3& direction) const;

 private:
  // A volume's shape along a ray: where it is, where its full-density core (inside the
  // edge fade) is, and how long its quadrature panels and camera segments are.
  struct VolumeChord {
    Interval shape;
    std::optional<Interval> core;
    double panel = 0, segment = 0;  // 0: uniform density, closed form
  };
  struct Volume {
    Shape shape;
    physics::Mat4 inverse;  // world to the unit shape (affine)
    Vec3 core_scale;        // the core as a scale of the unit shape (0: no core)
    bool uniform;           // no edge fade, no noise
    bool flat;              // a size of 0: no inside
  };
  std::optional<VolumeChord> chord(size_t i, const Vec3& origin, const Vec3& direction) const;
  Vec3 volume_optical_depth(size_t i, const VolumeChord& c, const Vec3& origin, const Vec3& direction, double t0,
                            double t1) const;
  double density_integral(size_t i, const Vec3& origin, const Vec3& direction, double t0, double t1, double panel) const;
  Vec3 volumes_optical_depth(const Vec3& origin, const Vec3& direction, double t0, double t1) const;
  Vec3 height_fog_optical_depth(double origin_y, double direction_y, double length) const;

  physics::MediaField field_;
  MediaQuadrature quadrature_;
  std::vector<Volume> volumes_;
};

}  // namespace volgraph::reference
