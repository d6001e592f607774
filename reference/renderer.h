// The CPU reference renderer's view of one ray (DESIGN.md units): the nearest surface by
// exact ray casting, its Lambertian reflection of every light with exact visibility
// (an any-hit shadow ray, no bias) and the media's transmittance toward the light, its
// emission, or the background; through the media, single scattering of every light
// integrated along the ray (single_scattering.h). Double precision throughout. Lighting
// comes from the CPU twins of the shaders (physics/lighting.h, phase.h, media.h). Pass
// parameters of the config (ambient terms, shadow-map settings, tone maps) are not part
// of the scene and are ignored.
//
// A scene with an atmosphere (graph/scene/scene.h Atmosphere) is seen through it, by
// reference/atmosphere_reference.h (double precision; orders ≥ 2 by Monte Carlo, seeded
// per camera ray by camera_ray_key, so an image is the same on every run and thread count):
// - a camera ray that meets no surface sees the sky from the camera's planet position
//   (every order, the sun's disk, the planet's ground beyond the scene) instead of the
//   scene's background;
// - the scene's lights arrive as physics::lights_through_atmosphere gives them (the sun
//   dimmed by the air above the scene's origin), and the sky lights everything with the
//   isotropic radiance L = physics::sky_ambient_radiance: a surface receives π·L, a medium
//   scatters σs·L (unoccluded);
// - along a camera ray the air and the scene's media are integrated together: up to the
//   surface, or to the far plane and then the sky beyond it, the light the air scatters
//   toward the camera and the media's are each dimmed by both (the air's transmittance by
//   physics' optical depth; its single scattering in the same adaptive quadrature as the
//   media's; its orders ≥ 2 as the Monte Carlo's A(t), the light they add on [0, t],
//   at kAirNodes equal steps to the ray's end and linear between them, integrated by parts
//   against the media's transmittance T: ∫T dA = T(D) A(D) + ∫σt T A dt). The air is lit
//   as the atmosphere reference lights it: the scene's objects and media cast no shadow
//   into it. Without media in the scene this is AtmosphereReference::aerial_perspective
//   in front of the surface.
// Without an atmosphere nothing of this runs: the image is what it was, bit for bit.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "graph/scene/scene.h"
#include "reference/bvh.h"
#include "reference/media.h"
#include "reference/scene_triangles.h"
#include "reference/single_scattering.h"

namespace volgraph::reference {

class AtmosphereReference;
struct AtmosphereReferenceSettings;

// The seed of the atmosphere's Monte Carlo paths for a camera ray of unit `direction`
// (its bit pattern mixed): the same ray gives the same paths.
uint64_t camera_ray_key(const Vec3& direction);

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
  // Throws std::runtime_error for a glTF file or texture that cannot be read. The
  // atmosphere's Monte Carlo takes AtmosphereReferenceSettings' defaults (64 paths a ray)
  // unless `atmosphere` is given; --spp N traces N rays a pixel, each with its own paths.
  explicit Renderer(const Scene& scene, const IntegrationSettings& integration = {});
  Renderer(const Scene& scene, const IntegrationSettings& integration, const AtmosphereReferenceSettings& atmosphere);

  // Linear radiance arriving at the camera along pixel (i, j) of a width × height frame:
  // the mean over samples_per_axis² sub-pixel positions on a regular grid (1: the pixel
  // centre of DESIGN.md's convention, as the GPU samples).
  Vec3 pixel_radiance(uint32_t i, uint32_t j, uint32_t width, uint32_t height, uint32_t samples_per_axis = 1) const;
  // Radiance arriving at the camera from direction `direction` (unit): surfaces are seen
  // within the camera's depth range [near, far] along its view axis, as the GPU clips;
  // media from the eye to the surface, or to the far plane where no surface is hit (the
  // background, or the atmosphere's sky, then lies behind the far plane).
  Vec3 camera_ray_radiance(const Vec3& direction) const;

  // The nearest surface along the camera ray of unit `direction` within the depth range.
  std::optional<SurfaceHit> surface_hit(const Vec3& direction) const;
  // Light reflected and emitted by the surface toward the camera (the sky's ambient
  // included).
  Vec3 surface_radiance(const SurfaceHit& hit) const;
  // Irradiance from `light` on a surface at `point` with unit normal `normal`: E·cos θ
  // times exact visibility times the media's transmittance toward the light.
  Vec3 light_arrival(const Light& light, const Vec3& point, const Vec3& normal) const;
  // Radiance per metre scattered (by every light, single scattering, and the sky's
  // ambient) and emitted toward the viewer at `point` by the media, for a camera ray of
  // unit `direction` (the air's not included).
  Vec3 in_scattering(const Vec3& point, const Vec3& direction) const;
  // Whether `light` sees `point` unblocked by any shadow-casting triangle (always for a
  // light that casts no shadows). Exact up to a start offset of 1e-9·(1 + |point|∞) m.
  bool light_visible(const Light& light, const Vec3& point) const;

  const Scene& scene() const { return scene_; }
  // The scene's lights as they arrive (physics::lights_through_atmosphere).
  const std::vector<Light>& lights() const { return lights_; }
  // The atmosphere's reference, null without an atmosphere.
  const AtmosphereReference* atmosphere() const { return atmosphere_.get(); }

  // Orders ≥ 2 of the air along a camera ray: the Monte Carlo's A(t) at these many equal
  // steps to the ray's end, linear between (only where the scene has media).
  static constexpr int kAirNodes = 4;
  const SceneTriangles& triangles() const { return triangles_; }
  const SceneMedia& media() const { return media_; }

 private:
  Vec3 atmosphere_ray_radiance(const Vec3& direction, const std::optional<SurfaceHit>& hit) const;

  const Scene& scene_;
  std::vector<Light> lights_;
  Vec3 sky_ambient_{0, 0, 0};  // L: a surface receives π·L, a medium scatters σs·L
  std::shared_ptr<const AtmosphereReference> atmosphere_;
  SceneTriangles triangles_;
  Bvh camera_bvh_;  // every triangle
  Bvh shadow_bvh_;  // the triangles of shadow-casting objects
  SceneMedia media_;
  IntegrationSettings integration_;
};

}  // namespace volgraph::reference
