// Shadow-map projections fitted to what they must cover (DESIGN.md conventions: metres,
// depth 0 at the near plane and 1 at the far one). A directional light's orthographic
// window is fitted to the receivers the camera can see — the camera frustum from its near
// plane to a shadow distance, clipped to the scene's box — with its depth range over the
// whole box (every caster), and its origin snapped to whole texels. A spot light keeps
// the perspective over its outer cone, its near and far fitted to the scene's box.
// CPU only: passes/shadow_map.cpp uploads the matrices; tests/unit/shadow_fit_test.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "graph/scene/scene.h"
#include "physics/camera.h"

namespace volgraph::physics {

// An axis-aligned box in world space (the scene's bounds); min ≤ max on every axis.
struct Box {
  Vec3 min{0, 0, 0};
  Vec3 max{0, 0, 0};
};

// An orthographic light projection: the light's view (a rotation and a translation) and,
// in that view's metres, the window x ∈ [left, right], y ∈ [bottom, top] and the depths
// along the light's direction [near, far].
struct OrthoFit {
  Mat4 view{1.0};
  double left = -1, right = 1, bottom = -1, top = 1;
  double near = 0, far = 1;
  Mat4 view_projection() const { return orthographic(left, right, bottom, top, near, far) * view; }
};

// The camera a directional fit follows and the shadow map it fits.
struct ReceiverView {
  Camera camera;
  double aspect = 1;              // of the frame the camera renders, width / height
  double distance = 0;            // metres of view depth that receive shadows; 0: to the scene's far end
  uint32_t texels_wide = 2048;    // the shadow map's size
  uint32_t texels_high = 2048;
};

// View depths (along the camera's forward axis) of the frustum slice that can receive
// shadows: the camera's near plane to `distance` (0: the deepest corner of the scene's
// box), never past the camera's far plane. far ≤ near: nothing in front of the camera.
struct DepthRange {
  double near = 0;
  double far = 0;
};
DepthRange receiver_depths(const Camera& camera, const Box& scene, double distance);

// The 8 corners of the camera frustum between two view depths; corner i has NDC
// x = bit 0 ? +1 : −1, y = bit 1 ? +1 : −1 and lies on the far plane when bit 2 is set.
std::array<Vec3, 8> frustum_slice_corners(const Camera& camera, double aspect, const DepthRange& depths);

// The vertices of the convex region a frustum slice (corners as above) and a box share;
// empty when they do not meet.
std::vector<Vec3> slice_box_intersection(const std::array<Vec3, 8>& slice, const Box& box);

// `box` grown to hold `points`.
Box including(const Box& box, std::span<const Vec3> points);

// The world box around a local media volume (its shape's box, transformed).
Box volume_bounds(const MediumVolume& volume);

// What a shadow map's view must hold: the geometry's box (casters and receivers) grown
// over the local media volumes, which the light reaches through volumetric shadows.
// Empty (nullopt) when there is neither.
std::optional<Box> shadowed_bounds(const std::optional<Box>& geometry, const Media& media);

// Directional light over the whole scene: a square window around its bounding sphere.
OrthoFit fit_directional_to_scene(const Vec3& direction, const Box& scene);

// Directional light over the receivers `view` sees (falls back to the whole scene when
// the camera sees none of the box).
OrthoFit fit_directional_to_camera(const Vec3& direction, const Box& scene, const ReceiverView& view);

// Spot light: perspective over the outer cone, near and far around the scene's box.
Mat4 fit_spot(const Light& light, const Box& scene);

}  // namespace volgraph::physics
