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
//
// Translucent surfaces (Material::translucency; reference/translucent_rays.cpp):
// - straight mode (IntegrationSettings::translucency, the default; what the GPU's
//   translucency pass models): the camera ray walks its hits in order. An opaque hit ends
//   it; a masked hole (coverage α × texture alpha < cutoff) is passed; a translucent hit is a
//   layer, physics::surface_layer (C = radiance + transmittance ⊙ C_behind), lit by the
//   irradiance an opaque surface there would get, its reflection seeing L_env (the
//   background, or under an atmosphere the sky's ambient radiance, as the GPU). Thin-walled
//   and shell objects: every face is a layer; solids: their front faces are layers whose
//   path inside runs to the object's next back face or the nearer opaque surface (the
//   material's thickness where neither lies ahead), their back faces are no layer (the GPU
//   culls them: a camera inside a solid sees through it unattenuated); surfaces inside a
//   solid are layers of their own (the GPU draws them too). Each layer is seen through the
//   media and air in front of it (physics::fogged_layer with the media integrated from the
//   camera to it). Layers that change nothing (radiance 0, transmittance 1) are dropped.
//   After max_layers layers the ray sees the background.
// - refracted mode: a solid's faces are interfaces, the ray bent by Bec's refraction
//   (entering 1/ior, leaving ior), Beer–Lambert inside, (1 − F) on each transmission;
//   the outer reflection sees L_env (cheap, and what the straight model uses), reflections
//   inside (total internal reflection, and F at the exit while the branch's weight stays
//   above min_branch_weight) are traced, up to max_bounces. Thin-walled and shell layers,
//   holes and solids of ior 1 are crossed as in straight mode (ior 1: the two modes agree
//   bit for bit without media). Media are integrated on each straight segment; the
//   atmosphere's air is not (a ray that escapes sees the sky from the camera).
// - shadow rays (both modes): each translucent surface between a point and a light
//   multiplies the light by its layer's transmittance at the shadow ray's angle (straight:
//   no caustics), a solid by Beer–Lambert over its chord; opaque casters block. The GPU's
//   translucent surfaces cast no shadows.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "graph/scene/scene.h"
#include "physics/translucency.h"
#include "reference/bvh.h"
#include "reference/media.h"
#include "reference/scene_triangles.h"
#include "reference/single_scattering.h"

namespace volgraph::reference {

class AtmosphereReference;
class CloudReference;
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
  bool front_facing = true;  // the ray meets the triangle's front (counter-clockwise) side
  Vec3 geometric_normal{0, 0, 1};  // the triangle's plane, unit, turned toward the viewer
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
  // The fraction of `light` that reaches `point` per channel: 0 behind an opaque caster,
  // the product of the translucent surfaces' transmittances between (1 with none).
  Vec3 light_transmittance(const Light& light, const Vec3& point) const;
  // Irradiance on a surface at `point` with unit normal `normal` from every light and the
  // sky's ambient.
  Vec3 surface_irradiance(const Vec3& point, const Vec3& normal) const;
  // The radiance the specular reflection of a translucent surface sees.
  const Vec3& environment() const { return environment_; }

  const Scene& scene() const { return scene_; }
  // The scene's lights as they arrive (physics::lights_through_atmosphere).
  const std::vector<Light>& lights() const { return lights_; }
  // The atmosphere's reference, null without an atmosphere.
  const AtmosphereReference* atmosphere() const { return atmosphere_.get(); }
  // The cloud layer's reference, null without a layer.
  const CloudReference* clouds() const { return clouds_.get(); }

  // Orders ≥ 2 of the air along a camera ray: the Monte Carlo's A(t) at these many equal
  // steps to the ray's end, linear between (only where the scene has media).
  static constexpr int kAirNodes = 4;
  const SceneTriangles& triangles() const { return triangles_; }
  const SceneMedia& media() const { return media_; }

 private:
  // The media's (and the air's) in-scattering S(0, t) and transmittance T(0, t) along
  // the camera ray.
  struct RayFog {
    Vec3 in_scattered{0, 0, 0};
    Vec3 transmittance{1, 1, 1};
  };
  RayFog atmosphere_fog(const Vec3& direction, double length) const;
  RayFog camera_fog(const Vec3& direction, double length) const;
  // What the camera ray sees at its end (the opaque `hit`, or the background or sky)
  // through the media in front of it.
  Vec3 ray_end_radiance(const Vec3& direction, const std::optional<SurfaceHit>& hit) const;
  double far_length(const Vec3& direction) const;

  // reference/translucent_rays.cpp
  struct Layer {
    double t = 0;
    physics::SurfaceLayer<double> layer;
  };
  struct LayeredRay {
    std::vector<Layer> layers;          // near to far
    std::optional<SurfaceHit> end;      // the opaque surface, none for the background
  };
  enum class SurfaceKind { opaque, hole, layer, solid_back_face };
  SurfaceHit surface_at(const TriangleHit& h, uint32_t triangle, const Vec3& direction) const;
  std::optional<SurfaceHit> next_surface(const Ray& ray) const;
  SurfaceKind surface_kind(const SurfaceHit& hit) const;
  const SurfaceMaterial& material_of(const SurfaceHit& hit) const;
  double solid_chord(const SurfaceHit& entry, const Ray& ray) const;
  physics::LayerInputs<double> layer_inputs(const SurfaceHit& hit, const Vec3& direction, double chord, bool lit, int channel = -1) const;
  Vec3 shadow_ray_transmittance(const Ray& ray) const;
  Vec3 inside_transmittance(const SurfaceMaterial& m, double length) const;
  LayeredRay layers_along(const Vec3& direction) const;
  Vec3 straight_ray_radiance(const Vec3& direction) const;
  Vec3 refracted_ray_radiance(const Vec3& direction) const;
  struct PathState {
    uint32_t layers = 0, bounces = 0;
    double weight = 1;
    int channel = -1;  // the one colour channel traced (a dispersive scene's), −1: all three at one IOR
  };
  Vec3 refracted_trace_per_channel(const Ray& ray) const;
  Vec3 refracted_trace(const Ray& ray, double segment_start, PathState state) const;
  Vec3 enter_solid(const SurfaceHit& entry, const Vec3& direction, PathState state) const;
  Vec3 inside_solid(const Ray& ray, uint32_t object, const SurfaceMaterial& medium, PathState state) const;
  Vec3 leave_solid(const SurfaceHit& exit, const Vec3& direction, PathState state) const;
  Vec3 segment_with_media(const Ray& ray, double start, double end, const Vec3& end_radiance) const;
  Vec3 miss_radiance(const Vec3& direction) const;

  const Scene& scene_;
  std::vector<Light> lights_;
  Vec3 sky_ambient_{0, 0, 0};  // L: a surface receives π·L, a medium scatters σs·L
  std::shared_ptr<const AtmosphereReference> atmosphere_;
  std::shared_ptr<const CloudReference> clouds_;  // the scene's cloud layer, null without one
  SceneTriangles triangles_;
  Bvh camera_bvh_;  // every triangle
  Bvh shadow_bvh_;  // the triangles of shadow-casting objects
  std::vector<uint32_t> shadow_triangles_;  // shadow_bvh_'s triangle k is triangles_' shadow_triangles_[k]
  bool see_through_casters_ = false;        // a shadow caster is translucent or masked
  bool dispersive_ = false;                 // a material has dispersion > 0: refracted mode traces each channel apart
  Vec3 environment_{0, 0, 0};
  SceneMedia media_;
  IntegrationSettings integration_;
};

}  // namespace volgraph::reference
