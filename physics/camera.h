// Camera and object transforms in DESIGN.md's conventions: right-handed, Y up, metres;
// a pinhole camera looking from `position` at `target`; pixel (i, j), row 0 at the top,
// looks through NDC x = (i + 0.5)/W·2 − 1, y = 1 − (j + 0.5)/H·2; depth 0 at the near
// plane and 1 at the far one (WebGPU's clip space). The GPU passes upload these
// matrices; the CPU reference generates the same rays.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "graph/scene/scene.h"

namespace volgraph::physics {

struct Mat4 {
  std::array<double, 16> m{};  // column-major, m[col * 4 + row], as GLSL
  double& operator()(int row, int col) { return m[size_t(col * 4 + row)]; }
  double operator()(int row, int col) const { return m[size_t(col * 4 + row)]; }
  static Mat4 identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r(i, i) = 1;
    return r;
  }
};

inline Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      for (int k = 0; k < 4; ++k) r(row, col) += a(row, k) * b(k, col);
  return r;
}

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 scaled(const Vec3& v, double s) { return {v[0] * s, v[1] * s, v[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Vec3 normalize(const Vec3& v) {
  const double l = std::sqrt(dot(v, v));
  return {v[0] / l, v[1] / l, v[2] / l};
}

// Column-major floats for a uniform block's mat4.
inline void to_floats(const Mat4& m, float* out) {
  for (size_t i = 0; i < 16; ++i) out[i] = float(m.m[i]);
}

// (x, y, z, w) → the transformed point divided by w.
inline Vec3 transform_point(const Mat4& t, const Vec3& p) {
  double out[4];
  for (int row = 0; row < 4; ++row) out[row] = t(row, 0) * p[0] + t(row, 1) * p[1] + t(row, 2) * p[2] + t(row, 3);
  return {out[0] / out[3], out[1] / out[3], out[2] / out[3]};
}

// World to view: the camera at the origin looking down −Z, +Y up.
inline Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up) {
  const Vec3 f = normalize(sub(target, eye));
  const Vec3 s = normalize(cross(f, up));
  const Vec3 u = cross(s, f);
  Mat4 r = Mat4::identity();
  for (int c = 0; c < 3; ++c) {
    r(0, c) = s[size_t(c)];
    r(1, c) = u[size_t(c)];
    r(2, c) = -f[size_t(c)];
  }
  r(0, 3) = -dot(s, eye);
  r(1, 3) = -dot(u, eye);
  r(2, 3) = dot(f, eye);
  return r;
}

// View to clip, right-handed, depth in [0, 1]: z = −near → 0, z = −far → 1.
inline Mat4 perspective(double fov_y_deg, double aspect, double near, double far) {
  const double t = 1.0 / std::tan(fov_y_deg * M_PI / 360.0);
  Mat4 r;
  r(0, 0) = t / aspect;
  r(1, 1) = t;
  r(2, 2) = far / (near - far);
  r(2, 3) = near * far / (near - far);
  r(3, 2) = -1;
  return r;
}

// View to clip for a box [l, r] × [b, t] × [−near, −far], depth in [0, 1].
inline Mat4 orthographic(double l, double r, double b, double t, double near, double far) {
  Mat4 o = Mat4::identity();
  o(0, 0) = 2 / (r - l);
  o(1, 1) = 2 / (t - b);
  o(2, 2) = 1 / (near - far);
  o(0, 3) = -(r + l) / (r - l);
  o(1, 3) = -(t + b) / (t - b);
  o(2, 3) = near / (near - far);
  return o;
}

// Object to world: scale, then rotate about X, then Y, then Z, then translate.
inline Mat4 model_matrix(const Transform& t) {
  auto rotation = [](int axis, double deg) {
    const double c = std::cos(deg * M_PI / 180.0), s = std::sin(deg * M_PI / 180.0);
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    Mat4 r = Mat4::identity();
    r(a, a) = c;
    r(a, b) = -s;
    r(b, a) = s;
    r(b, b) = c;
    return r;
  };
  Mat4 scale = Mat4::identity(), translate = Mat4::identity();
  for (int i = 0; i < 3; ++i) {
    scale(i, i) = t.scale[size_t(i)];
    translate(i, 3) = t.translate[size_t(i)];
  }
  return translate * rotation(2, t.rotate_deg[2]) * rotation(1, t.rotate_deg[1]) * rotation(0, t.rotate_deg[0]) * scale;
}

// The inverse transpose of a transform's 3×3 part (in a Mat4): it carries normals.
inline Mat4 normal_matrix(const Mat4& t) {
  auto a = [&](int r, int c) { return t(r, c); };
  const double det = a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
                     a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
  Mat4 r = Mat4::identity();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      // (A⁻¹)ᵀ[row][col] = cofactor(row, col) / det
      const int r0 = (row + 1) % 3, r1 = (row + 2) % 3, c0 = (col + 1) % 3, c1 = (col + 2) % 3;
      r(row, col) = (a(r0, c0) * a(r1, c1) - a(r0, c1) * a(r1, c0)) / det;
    }
  }
  return r;
}

inline Mat4 view_projection(const Camera& c, double aspect) {
  return perspective(c.fov_y_deg, aspect, c.near, c.far) * look_at(c.position, c.target, c.up);
}

// The camera's rays by NDC (shaders/include/view_rays.glsl): the ray through NDC (x, y)
// is forward + x·right + y·up, scaled so that its component along forward is 1 — a point
// at view depth z along it is position + z·ray.
struct ViewRays {
  Vec3 position, forward, right, up;
};

inline ViewRays view_rays(const Camera& c, double aspect) {
  const double t = std::tan(c.fov_y_deg * M_PI / 360.0);
  const Vec3 f = normalize(sub(c.target, c.position));
  const Vec3 s = normalize(cross(f, c.up));
  const Vec3 u = cross(s, f);
  return {c.position, f, scaled(s, t * aspect), scaled(u, t)};
}

inline Vec3 view_ray(const ViewRays& v, double ndc_x, double ndc_y) {
  return add(v.forward, add(scaled(v.right, ndc_x), scaled(v.up, ndc_y)));
}

// Where world point p lies in the view (shaders/include/view_rays.glsl `view_uvz`): the
// texture coordinate across the frame (u right, v down) and the view depth z (m).
struct ViewUvz {
  double u = 0, v = 0, z = 0;
};

inline ViewUvz view_uvz(const ViewRays& v, const Vec3& p) {
  const Vec3 d = sub(p, v.position);
  const double z = dot(d, v.forward);
  const double along_x = dot(d, v.right) / dot(v.right, v.right), along_y = dot(d, v.up) / dot(v.up, v.up);
  const double inverse_z = 1.0 / std::max(z, 1e-20);
  return {0.5 + 0.5 * along_x * inverse_z, 0.5 - 0.5 * along_y * inverse_z, z};
}

// The direction (unit, world space) pixel (i, j) of a W × H frame looks along.
inline Vec3 pixel_ray(const Camera& c, uint32_t width, uint32_t height, double i, double j) {
  const double x = (i + 0.5) / width * 2 - 1, y = 1 - (j + 0.5) / height * 2;
  return normalize(view_ray(view_rays(c, double(width) / height), x, y));
}

// The inverse of an affine transform (a model matrix): world to the object's space.
inline Mat4 inverse_affine(const Mat4& m) {
  const Mat4 inverse_transpose = normal_matrix(m);
  Mat4 r = Mat4::identity();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) r(row, col) = inverse_transpose(col, row);
  }
  for (int row = 0; row < 3; ++row) r(row, 3) = -(r(row, 0) * m(0, 3) + r(row, 1) * m(1, 3) + r(row, 2) * m(2, 3));
  return r;
}

// The inverse of any invertible 4×4 matrix (a projection too): Gauss–Jordan elimination
// with partial pivoting, in double.
inline Mat4 inverse(const Mat4& m) {
  Mat4 a = m, r = Mat4::identity();
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 4; ++row) {
      if (std::abs(a(row, col)) > std::abs(a(pivot, col))) pivot = row;
    }
    for (int k = 0; k < 4; ++k) {
      std::swap(a(col, k), a(pivot, k));
      std::swap(r(col, k), r(pivot, k));
    }
    const double scale = 1.0 / a(col, col);
    for (int k = 0; k < 4; ++k) {
      a(col, k) *= scale;
      r(col, k) *= scale;
    }
    for (int row = 0; row < 4; ++row) {
      if (row == col) continue;
      const double f = a(row, col);
      for (int k = 0; k < 4; ++k) {
        a(row, k) -= f * a(col, k);
        r(row, k) -= f * r(col, k);
      }
    }
  }
  return r;
}

}  // namespace volgraph::physics
