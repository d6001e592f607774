// Shadow-map fitting (physics/shadow_fit.h): the fitted directional window holds
// every receiver the camera sees (sampled densely) and every caster's depth, is far
// smaller than the whole-scene window over a large ground, and a moving camera shifts it
// by whole texels only; a spot light's near and far hug the scene's bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/shadow_fit.h"

namespace volgraph::physics {
namespace {

// Receivers project into the light's clip volume exactly, up to double rounding.
constexpr double kClipTolerance = 1e-9;
// Window edges on whole texels, up to double rounding of a few thousand texels.
constexpr double kTexelTolerance = 1e-6;

const Vec3 kSun{-0.5, -0.6, -0.4};

// A 200 m ground plane (y = 0) with a 1 m box standing on it at the origin.
Box ground_and_box() { return {{-100, 0, -100}, {100, 1, 100}}; }

Camera camera_at(const Vec3& position, const Vec3& target) {
  Camera c;
  c.position = position;
  c.target = target;
  c.fov_y_deg = 45;
  c.near = 0.1;
  c.far = 1000;
  return c;
}

// A camera 5 m from the box, looking down at it.
ReceiverView looking_at_the_box(double distance = 0) {
  return {camera_at({0, 3, 4}, {0, 0.5, 0}), 16.0 / 9.0, distance, 2048, 2048};
}

// Corner i of a box: bit 0 picks max x, bit 1 max y, bit 2 max z.
Vec3 corner(const Box& b, int i) {
  return {i & 1 ? b.max[0] : b.min[0], i & 2 ? b.max[1] : b.min[1], i & 4 ? b.max[2] : b.min[2]};
}

// Every corner of the box projects to a depth in [0, 1].
void expect_box_in_depth_range(const Mat4& clip, const Box& box) {
  for (int i = 0; i < 8; ++i) {
    const double depth = transform_point(clip, corner(box, i))[2];
    EXPECT_GE(depth, 0) << "corner " << i;
    EXPECT_LE(depth, 1) << "corner " << i;
  }
}

bool inside(const Box& b, const Vec3& p) {
  for (size_t k = 0; k < 3; ++k) {
    if (p[k] < b.min[k] || p[k] > b.max[k]) return false;
  }
  return true;
}

Vec3 forward_of(const Camera& c) { return normalize(sub(c.target, c.position)); }

// Points of the camera's frustum slice on a grid of NDC x, y and view depth, kept where
// they lie in the scene's box (the receivers), plus a grid over the box kept where the
// camera sees it within the slice.
std::vector<Vec3> receiver_samples(const ReceiverView& view, const Box& scene) {
  const DepthRange depths = receiver_depths(view.camera, scene, view.distance);
  const Vec3 forward = forward_of(view.camera);
  const uint32_t wide = 64, high = uint32_t(std::lround(64 / view.aspect));
  std::vector<Vec3> samples;
  const int n = 40;
  for (int a = 0; a <= n; ++a) {
    for (int b = 0; b <= n; ++b) {
      const Vec3 ray = pixel_ray(view.camera, wide, high, -0.5 + wide * double(a) / n, -0.5 + high * double(b) / n);
      for (int d = 0; d <= 4 * n; ++d) {
        const double depth = depths.near + (depths.far - depths.near) * d / (4 * n);
        const Vec3 p = add(view.camera.position, scaled(ray, depth / dot(ray, forward)));
        if (inside(scene, p)) samples.push_back(p);
      }
    }
  }
  const Mat4 camera_clip = view_projection(view.camera, double(wide) / high);
  for (int i = 0; i <= 200; ++i) {
    for (int j = 0; j <= 10; ++j) {
      for (int k = 0; k <= 200; ++k) {
        const Vec3 p{scene.min[0] + (scene.max[0] - scene.min[0]) * i / 200, scene.min[1] + (scene.max[1] - scene.min[1]) * j / 10,
                     scene.min[2] + (scene.max[2] - scene.min[2]) * k / 200};
        const double depth = dot(sub(p, view.camera.position), forward);
        if (depth < depths.near || depth > depths.far) continue;
        const Vec3 ndc = transform_point(camera_clip, p);
        if (std::abs(ndc[0]) <= 1 && std::abs(ndc[1]) <= 1) samples.push_back(p);
      }
    }
  }
  return samples;
}

struct Scenario {
  const char* name;
  ReceiverView view;
  Vec3 light;
};

std::vector<Scenario> scenarios() {
  return {
      {"looking at the box, sun", looking_at_the_box(), kSun},
      {"looking at the box, 8 m shadow distance", looking_at_the_box(8), kSun},
      {"towards the horizon, light straight down", {camera_at({0, 1.5, 10}, {0, 1, 0}), 16.0 / 9.0, 0, 2048, 2048}, {0, -1, 0}},
      {"towards the horizon, grazing light", {camera_at({0, 1.5, 10}, {0, 1, 0}), 1.0, 40, 1024, 512}, {1, -0.05, 0.2}},
      {"from inside the box's height, near an edge", {camera_at({95, 0.5, 90}, {0, 0.5, 0}), 2.0, 0, 2048, 2048}, kSun},
  };
}

TEST(ShadowFit, EveryVisibleReceiverProjectsInsideTheLightsClipVolume) {
  const Box scene = ground_and_box();
  for (const Scenario& s : scenarios()) {
    SCOPED_TRACE(s.name);
    const Mat4 light_clip = fit_directional_to_camera(s.light, scene, s.view).view_projection();
    const std::vector<Vec3> samples = receiver_samples(s.view, scene);
    ASSERT_GT(samples.size(), 1000u);
    Vec3 lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
    for (const Vec3& p : samples) {
      const Vec3 ndc = transform_point(light_clip, p);
      ASSERT_LE(std::abs(ndc[0]), 1 + kClipTolerance) << p[0] << ", " << p[1] << ", " << p[2];
      ASSERT_LE(std::abs(ndc[1]), 1 + kClipTolerance) << p[0] << ", " << p[1] << ", " << p[2];
      ASSERT_GE(ndc[2], -kClipTolerance) << p[0] << ", " << p[1] << ", " << p[2];
      ASSERT_LE(ndc[2], 1 + kClipTolerance) << p[0] << ", " << p[1] << ", " << p[2];
      for (size_t k = 0; k < 2; ++k) lo[k] = std::min(lo[k], ndc[k]), hi[k] = std::max(hi[k], ndc[k]);
    }
    // Tight: a side is at most 2^(1/4) × (1 + one texel) the receivers' extent, so they
    // span at least 2 / 1.19 ≈ 1.68 of the 2 NDC units, less the sampling's gaps.
    EXPECT_GT(hi[0] - lo[0], 1.6);
    EXPECT_GT(hi[1] - lo[1], 1.6);
  }
}

TEST(ShadowFit, EverySceneCornerProjectsToADepthInZeroOne) {
  const Box scene = ground_and_box();
  for (const Scenario& s : scenarios()) {
    SCOPED_TRACE(s.name);
    expect_box_in_depth_range(fit_directional_to_camera(s.light, scene, s.view).view_projection(), scene);
  }
}

TEST(ShadowFit, FittedWindowIsAtLeastTenTimesSmallerThanTheWholeScenes) {
  const Box scene = ground_and_box();
  const OrthoFit whole = fit_directional_to_scene(kSun, scene);
  const OrthoFit fitted = fit_directional_to_camera(kSun, scene, looking_at_the_box());
  const double whole_area = (whole.right - whole.left) * (whole.top - whole.bottom);
  const double fitted_area = (fitted.right - fitted.left) * (fitted.top - fitted.bottom);
  EXPECT_NEAR(whole_area, 4 * (100 * 100 + 0.25 + 100 * 100), 1e-6);  // the square around the bounding sphere
  EXPECT_LE(10 * fitted_area, whole_area) << "fitted " << fitted_area << " m², whole scene " << whole_area << " m²";
}

// The window's origin in texels of its own size, and how far it is from a whole number.
double texels_off_grid(double origin, double texel) { return std::abs(origin / texel - std::round(origin / texel)); }

TEST(ShadowFit, MovingTheCameraShiftsTheWindowByWholeTexels) {
  const Box scene = ground_and_box();
  const ReceiverView before = looking_at_the_box(30);
  const OrthoFit a = fit_directional_to_camera(kSun, scene, before);
  const double texel_x = (a.right - a.left) / before.texels_wide, texel_y = (a.top - a.bottom) / before.texels_high;
  EXPECT_LT(texels_off_grid(a.left, texel_x), kTexelTolerance);
  EXPECT_LT(texels_off_grid(a.bottom, texel_y), kTexelTolerance);
  for (const double texels : {0.37, 7.61}) {
    SCOPED_TRACE(texels);
    const Vec3 step{texels * texel_x, 0, 0.6 * texels * texel_x};
    ReceiverView after = before;
    after.camera.position = add(before.camera.position, step);
    after.camera.target = add(before.camera.target, step);
    const OrthoFit b = fit_directional_to_camera(kSun, scene, after);
    ASSERT_NEAR(b.right - b.left, a.right - a.left, 1e-12 * (a.right - a.left));  // the same size, so the same texels
    ASSERT_NEAR(b.top - b.bottom, a.top - a.bottom, 1e-12 * (a.top - a.bottom));
    EXPECT_LT(texels_off_grid(b.left - a.left, texel_x), kTexelTolerance);
    EXPECT_LT(texels_off_grid(b.bottom - a.bottom, texel_y), kTexelTolerance);
    if (texels > 1) EXPECT_GE(std::abs(b.left - a.left) + std::abs(b.bottom - a.bottom), texel_x);  // it did move
  }
}

TEST(ShadowFit, ReceiverDepthsRunFromTheNearPlaneToTheDistanceOrTheScenesFarEnd) {
  const Box scene = ground_and_box();
  const Camera camera = looking_at_the_box().camera;
  double deepest = 0;
  for (int i = 0; i < 8; ++i) deepest = std::max(deepest, dot(sub(corner(scene, i), camera.position), forward_of(camera)));
  const DepthRange to_scene = receiver_depths(camera, scene, 0);
  EXPECT_EQ(to_scene.near, camera.near);
  EXPECT_NEAR(to_scene.far, deepest, 1e-12);
  EXPECT_EQ(receiver_depths(camera, scene, 8).far, 8);
  EXPECT_EQ(receiver_depths(camera, scene, 5000).far, camera.far);
}

TEST(ShadowFit, NestedSolidsShareTheInnerOne) {
  const Camera camera = camera_at({0, 0, 0}, {0, 0, -1});
  const std::array<Vec3, 8> slice = frustum_slice_corners(camera, 1.0, {1, 2});
  const std::vector<Vec3> all_of_slice = slice_box_intersection(slice, {{-10, -10, -10}, {10, 10, 10}});
  EXPECT_EQ(all_of_slice.size(), 8u);
  const std::vector<Vec3> all_of_box = slice_box_intersection(slice, {{-0.1, -0.1, -1.6}, {0.1, 0.1, -1.4}});
  EXPECT_EQ(all_of_box.size(), 8u);
  EXPECT_TRUE(slice_box_intersection(slice, {{5, 5, 5}, {6, 6, 6}}).empty());
}

TEST(ShadowFit, SpotFarHugsTheSceneAndNearHoldsCastersCloseToTheLight) {
  Light spot;
  spot.type = LightType::spot;
  spot.position = {0, 50, 0};
  spot.direction = {0, -1, 0};
  spot.outer_cone_deg = 30;
  const Box scene = ground_and_box();  // 49 m to 50 m below the light
  const Mat4 clip = fit_spot(spot, scene);
  expect_box_in_depth_range(clip, scene);
  EXPECT_GT(transform_point(clip, {0, 50 - 1.02 * 50, 0})[2], 1);  // far within 2 % of the deepest corner
  const Box reaching_the_light{{-1, 0, -1}, {1, 49.97, 1}};        // a caster 3 cm below the light
  expect_box_in_depth_range(fit_spot(spot, reaching_the_light), reaching_the_light);
}

// A box of edges 2 × 4 × 6 turned 90° about y and moved to (10, 0, 0) spans x 7–13,
// y −2–2, z −1–1; a sphere's box is its radius each way; an ellipsoid's its radii.
TEST(ShadowFit, MediaVolumeBoundsAreTheTransformedShapesBox) {
  MediumVolume box;
  box.size = {2, 4, 6};
  box.transform.rotate_deg = {0, 90, 0};
  box.transform.translate = {10, 0, 0};
  const Box b = volume_bounds(box);
  const Vec3 want_min{7, -2, -1}, want_max{13, 2, 1};
  for (size_t a = 0; a < 3; ++a) {
    EXPECT_NEAR(b.min[a], want_min[a], 1e-9) << a;
    EXPECT_NEAR(b.max[a], want_max[a], 1e-9) << a;
  }
  MediumVolume sphere;
  sphere.shape = Shape::sphere;
  sphere.size = {3, 0, 0};
  EXPECT_NEAR(volume_bounds(sphere).max[2], 3, 1e-12);
  MediumVolume ellipsoid;
  ellipsoid.shape = Shape::ellipsoid;
  ellipsoid.size = {1, 2, 3};
  EXPECT_NEAR(volume_bounds(ellipsoid).min[1], -2, 1e-12);
}

// The shadow map's view grows over the media volumes, and a scene without geometry is
// bounded by its volumes alone (none: nothing to bound).
TEST(ShadowFit, ShadowedBoundsHoldGeometryAndMediaVolumes) {
  Media media;
  EXPECT_FALSE(shadowed_bounds(std::nullopt, media));
  MediumVolume cloud;
  cloud.transform.translate = {0, 20, 0};
  media.volumes.push_back(cloud);
  const std::optional<Box> alone = shadowed_bounds(std::nullopt, media);
  ASSERT_TRUE(alone);
  EXPECT_DOUBLE_EQ(alone->max[1], 20.5);
  const std::optional<Box> both = shadowed_bounds(Box{{-5, -1, -5}, {5, 1, 5}}, media);
  EXPECT_DOUBLE_EQ(both->min[0], -5);
  EXPECT_DOUBLE_EQ(both->max[1], 20.5);
  EXPECT_DOUBLE_EQ(both->min[1], -1);
}

// The general inverse undoes a perspective projection times a view (the shadow map's
// clip_to_world): every entry of inverse(M)·M within 1e-12 of the identity.
TEST(ShadowFit, InverseUndoesAProjection) {
  const Mat4 m = perspective(40, 1.5, 0.05, 80) * look_at({1, 2, 3}, {0, 0, -4}, {0, 1, 0});
  const Mat4 product = inverse(m) * m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(product[c][r], r == c ? 1.0 : 0.0, 1e-12) << r << ", " << c;
  }
}

}  // namespace
}  // namespace volgraph::physics
