// Temporal accumulation's CPU twins (physics/camera.h view_uvz, froxel.h
// froxel_uvw, temporal.h temporal_blend) where the answer is known exactly: a froxel's
// centre reprojects onto its own texel centre with an unchanged camera; after a known
// translation or rotation it lands where geometry says; points behind the camera, off the
// frame or outside [near, far] are outside; the blend averages its first frames equally
// and then weighs new frames by alpha.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/froxel.h"
#include "physics/temporal.h"

namespace volgraph::physics {
namespace {

// Camera at the origin looking down −Z, 90° vertical field of view, square frame: the
// ray through NDC (x, y) is (x, y, −1).
Camera square_camera() {
  Camera c;
  c.position = {0, 0, 0};
  c.target = {0, 0, -1};
  c.fov_y_deg = 90;
  c.near = 0.5;
  c.far = 4;
  return c;
}

TEST(FroxelReprojection, EveryFroxelCentreReprojectsOntoItselfWithAnUnchangedCamera) {
  Camera camera;
  camera.position = {1, 2, 3};
  camera.target = {-2, 1, -4};
  camera.fov_y_deg = 50;
  const double aspect = 16.0 / 9.0;
  const ViewRays view = view_rays(camera, aspect);
  for (const FroxelDistribution distribution : {FroxelDistribution::linear, FroxelDistribution::exponential}) {
    const FroxelRange range{0.1, 40, distribution};
    const int size[3] = {20, 9, 16};
    for (int i = 0; i < size[0]; i += 3) {
      for (int j = 0; j < size[1]; j += 2) {
        for (int k = 0; k < size[2]; k += 3) {
          const double u = (i + 0.5) / size[0], v = (j + 0.5) / size[1], w = (k + 0.5) / size[2];
          const Vec3 p = add(view.position, scaled(view_ray(view, 2 * u - 1, 1 - 2 * v), froxel_depth(range, w)));
          const FroxelUvw at = froxel_uvw(view, range, p);
          EXPECT_TRUE(at.inside);
          EXPECT_NEAR(at.u, u, 1e-12);
          EXPECT_NEAR(at.v, v, 1e-12);
          EXPECT_NEAR(at.w, w, 1e-12);
        }
      }
    }
  }
}

TEST(FroxelReprojection, AfterATranslationAPointLandsWhereGeometrySays) {
  const Camera before = square_camera();
  Camera after = before;
  after.position = {1, 0, 0};
  after.target = {1, 0, -1};
  const FroxelRange range{0.5, 4, FroxelDistribution::linear};
  const Vec3 p = {1, 0.5, -2};
  // Seen from the origin: depth 2, NDC (0.5, 0.25) → u = 0.75, v = 0.375; w = (2 − 0.5)/3.5.
  const FroxelUvw from_before = froxel_uvw(view_rays(before, 1), range, p);
  EXPECT_TRUE(from_before.inside);
  EXPECT_NEAR(from_before.u, 0.75, 1e-12);
  EXPECT_NEAR(from_before.v, 0.375, 1e-12);
  EXPECT_NEAR(from_before.w, 1.5 / 3.5, 1e-12);
  // From x = 1 the same point is straight ahead in x: u = 0.5, v unchanged.
  const FroxelUvw from_after = froxel_uvw(view_rays(after, 1), range, p);
  EXPECT_NEAR(from_after.u, 0.5, 1e-12);
  EXPECT_NEAR(from_after.v, 0.375, 1e-12);
  EXPECT_NEAR(from_after.w, 1.5 / 3.5, 1e-12);
  // A step forward by 1 m brings it to depth 1: NDC (1, 0.5) → u = 1, on the frame's edge.
  after.position = {0, 0, -1};
  after.target = {0, 0, -2};
  const FroxelUvw closer = froxel_uvw(view_rays(after, 1), range, p);
  EXPECT_NEAR(closer.u, 1.0, 1e-12);
  EXPECT_NEAR(closer.v, 0.25, 1e-12);
  EXPECT_NEAR(closer.w, 0.5 / 3.5, 1e-12);
}

TEST(FroxelReprojection, AfterARotationAPointLandsWhereGeometrySays) {
  Camera turned = square_camera();
  turned.target = {-1, 0, -1};  // 45° to the left: the point straight ahead before is on the right edge
  const FroxelRange range{0.5, 4, FroxelDistribution::exponential};
  const Vec3 p = {0, 0, -2};
  const FroxelUvw at = froxel_uvw(view_rays(turned, 1), range, p);
  EXPECT_NEAR(at.u, 1.0, 1e-12);  // NDC x = tan 45° / tan 45°
  EXPECT_NEAR(at.v, 0.5, 1e-12);
  // View depth along the new forward: 2·cos 45°.
  EXPECT_NEAR(at.w, std::log(std::sqrt(2.0) / 0.5) / std::log(4 / 0.5), 1e-12);
}

TEST(FroxelReprojection, PointsTheViewDoesNotSeeAreOutside) {
  const ViewRays view = view_rays(square_camera(), 1);
  const FroxelRange range{0.5, 4, FroxelDistribution::linear};
  EXPECT_FALSE(froxel_uvw(view, range, {0, 0, 1}).inside);        // behind the camera
  EXPECT_FALSE(froxel_uvw(view, range, {0, 0, -0.25}).inside);    // nearer than near
  EXPECT_FALSE(froxel_uvw(view, range, {0, 0, -5}).inside);       // beyond far
  EXPECT_FALSE(froxel_uvw(view, range, {2.5, 0, -2}).inside);     // right of the frame
  EXPECT_FALSE(froxel_uvw(view, range, {0, -2.2, -2}).inside);    // below it
  EXPECT_TRUE(froxel_uvw(view, range, {1.9, -1.9, -2}).inside);   // just inside a corner
  EXPECT_NEAR(view_uvz(view, {0, 0, 1}).z, -1, 1e-12);
}

TEST(TemporalBlend, TheFirstFramesAverageEquallyThenAlphaWeighsNewFrames) {
  Accumulated<double> h{};
  const double alpha = 0.25;
  const double values[] = {1, 2, 3, 4, 10, 10};
  double sum = 0;
  for (int f = 0; f < 4; ++f) {
    h = temporal_blend(values[f], h, f > 0, alpha);
    sum += values[f];
    EXPECT_NEAR(h.value, sum / (f + 1), 1e-12) << "frame " << f;
    EXPECT_EQ(h.frames, f + 1.0);
  }
  h = temporal_blend(values[4], h, true, alpha);  // capped at 1/alpha = 4 frames: weight alpha
  EXPECT_NEAR(h.value, 0.75 * 2.5 + 0.25 * 10, 1e-12);
  EXPECT_EQ(h.frames, 4.0);
  h = temporal_blend(7.0, h, false, alpha);  // no history: this frame alone
  EXPECT_EQ(h.value, 7.0);
  EXPECT_EQ(h.frames, 1.0);
}

}  // namespace
}  // namespace volgraph::physics
