// The CPU reference renderer's view of one ray (DESIGN.md units): the nearest surface by
// exact ray casting, its Lambertian reflection of every light with exact visibility
// (an any-hit shadow ray, no bias) and the media's transmittance toward the light, its
// emission, or the background; through the media, single scattering of every light
// integrated along the ray (single_scattering.h). Double precision throughout. Lighting
// comes from the CPU twins of the shaders (physics/lighting.h, phase.h, media.h). Pass
// parameters of the config (ambient terms, shadow-map settings, tone maps) are not part
// of the scene and are ignored.
#pragma once

#include <cstdint>
#include <optional>

#include "graph/scene/scene.h"
#include "reference/bvh.h"
#include "reference/media.h"
#include "reference/scene_triangles.h"
#include "reference/single_scattering.h"

namespace volgraph::reference {

// Where a camera ray meets the scene, with what the fragment shader would see there.
struct SurfaceHit {
  double t = 0;
  Vec3 position{0, 0, 0};
  Vec3 normal{0, 0, 1};    // interpolated vertex normal, unit, turned toward the viewer
  uint32_t triangle = 0;   // index into SceneTriangles
  double u = 0, v = 0;     // interpolated texture coordinate
};

class Renderer {
 public:
  // Throws std::runtime_error for a glTF file or texture that cannot be read.
  explicit Renderer(const Scene& scene, const IntegrationSettings& integration = {});

  // Linear radiance arriving at the camera along pixel (i, j) of a width × height frame:
  // the mean over samples_per_axis² sub-pixel positions on a regular grid (1: the pixel
  // centre of DESIGN.md's convention, as the GPU samples).
  Vec3 pixel_radiance(uint32_t i, uint32_t j, uint32_t width, uint32_t height, uint32_t samples_per_axis = 1) const;
  // Radiance arriving at the camera from direction `direction` (unit): surfaces are seen
  // within the camera's depth range [near, far] along its view axis, as the GPU clips;
  // media from the eye to the surface, or to the far plane where no surface is hit (the
  // background then lies behind the far plane).
  Vec3 camera_ray_radiance(const Vec3& direction) const;

  // The nearest surface along the camera ray of unit `direction` within the depth range.
  std::optional<SurfaceHit> surface_hit(const Vec3& direction) const;
  // Light reflected and emitted by the surface toward the camera.
  Vec3 surface_radiance(const SurfaceHit& hit) const;
  // Irradiance from `light` on a surface at `point` with unit normal `normal`: E·cos θ
  // times exact visibility times the media's transmittance toward the light.
  Vec3 light_arrival(const Light& light, const Vec3& point, const Vec3& normal) const;
  // Radiance per metre scattered (by every light, single scattering) and emitted toward
  // the viewer at `point` by the media, for a camera ray of unit `direction`.
  Vec3 in_scattering(const Vec3& point, const Vec3& direction) const;
  // Whether `light` sees `point` unblocked by any shadow-casting triangle (always for a
  // light that casts no shadows). Exact up to a start offset of 1e-9·(1 + |point|∞) m.
  bool light_visible(const Light& light, const Vec3& point) const;

  const Scene& scene() const { return scene_; }
  const SceneTriangles& triangles() const { return triangles_; }
  const SceneMedia& media() const { return media_; }

 private:
  const Scene& scene_;
  SceneTriangles triangles_;
  Bvh camera_bvh_;  // every triangle
  Bvh shadow_bvh_;  // the triangles of shadow-casting objects
  SceneMedia media_;
  IntegrationSettings integration_;
};

}  // namespace volgraph::reference
