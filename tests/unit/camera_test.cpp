// Camera maths against DESIGN.md's conventions, and the GPU's matrices against the
// CPU's rays (what the reference renderer will use): the same pixel, the same line.
#include <gtest/gtest.h>

#include "physics/camera.h"

namespace volgraph::physics {
namespace {

Camera test_camera() {
  Camera c;
  c.position = {1, 2, 5};
  c.target = {0, 0.5, 0};
  c.fov_y_deg = 50;
  c.near = 0.1;
  c.far = 100;
  return c;
}

TEST(Camera, TargetProjectsToTheCentreAndNearFarToZeroAndOne) {
  const Camera c = test_camera();
  const Mat4 vp = view_projection(c, 16.0 / 9.0);
  const Vec3 centre = transform_point(vp, c.target);
  EXPECT_NEAR(centre[0], 0, 1e-12);
  EXPECT_NEAR(centre[1], 0, 1e-12);
  const Vec3 f = normalize(sub(c.target, c.position));
  auto along = [&](double d) { return Vec3{c.position[0] + d * f[0], c.position[1] + d * f[1], c.position[2] + d * f[2]}; };
  EXPECT_NEAR(transform_point(vp, along(c.near))[2], 0, 1e-12);
  EXPECT_NEAR(transform_point(vp, along(c.far))[2], 1, 1e-9);
}

TEST(Camera, UpInTheWorldIsUpInNdc) {
  const Camera c = test_camera();
  const Mat4 vp = view_projection(c, 1.0);
  const Vec3 above = transform_point(vp, {c.target[0], c.target[1] + 0.1, c.target[2]});
  EXPECT_GT(above[1], 0);  // NDC +y is the top of the image (row 0)
}

TEST(Camera, PixelRaysLandOnTheirPixelsNdc) {
  const Camera c = test_camera();
  const uint32_t w = 64, h = 36;
  const Mat4 vp = view_projection(c, double(w) / h);
  for (const auto& [i, j] : {std::pair{0.0, 0.0}, {63.0, 0.0}, {31.0, 17.0}, {10.0, 35.0}}) {
    const Vec3 d = pixel_ray(c, w, h, i, j);
    const Vec3 p{c.position[0] + 3 * d[0], c.position[1] + 3 * d[1], c.position[2] + 3 * d[2]};
    const Vec3 ndc = transform_point(vp, p);
    EXPECT_NEAR(ndc[0], (i + 0.5) / w * 2 - 1, 1e-12) << i << ", " << j;
    EXPECT_NEAR(ndc[1], 1 - (j + 0.5) / h * 2, 1e-12) << i << ", " << j;
  }
}

TEST(Camera, ModelMatrixScalesThenRotatesXYZThenTranslates) {
  Transform t;
  t.scale = {2, 1, 1};
  t.rotate_deg = {0, 90, 0};  // +X goes to −Z about Y (right-handed)
  t.translate = {0, 0, 10};
  const Vec3 p = transform_point(model_matrix(t), {1, 0, 0});
  EXPECT_NEAR(p[0], 0, 1e-12);
  EXPECT_NEAR(p[1], 0, 1e-12);
  EXPECT_NEAR(p[2], 8, 1e-12);
  Transform x;
  x.rotate_deg = {90, 0, 0};  // +Y goes to +Z about X
  const Vec3 q = transform_point(model_matrix(x), {0, 1, 0});
  EXPECT_NEAR(q[2], 1, 1e-12);
}

TEST(Camera, OrthographicMapsItsBoxToClipSpace) {
  const Mat4 o = orthographic(-2, 2, -1, 3, 0.5, 10);
  const Vec3 a = transform_point(o, {-2, -1, -0.5}), b = transform_point(o, {2, 3, -10});
  EXPECT_NEAR(a[0], -1, 1e-12);
  EXPECT_NEAR(a[1], -1, 1e-12);
  EXPECT_NEAR(a[2], 0, 1e-12);
  EXPECT_NEAR(b[0], 1, 1e-12);
  EXPECT_NEAR(b[1], 1, 1e-12);
  EXPECT_NEAR(b[2], 1, 1e-12);
}

}  // namespace
}  // namespace volgraph::physics
