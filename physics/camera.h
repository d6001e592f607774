// Camera and object transforms in DESIGN.md's conventions: right-handed, Y up, metres;
// a pinhole camera looking from `position` at `target`; pixel (i, j), row 0 at the top,
// looks through NDC x = (i + 0.5)/W·2 − 1, y = 1 − (j + 0.5)/H·2; depth 0 at the near
// plane and 1 at the far one (WebGPU's clip space). The GPU passes upload these
// matrices; the CPU reference generates the same rays.
//
// Matrices are GLM's, as GLSL's: column-major, m[col][row], and GLM's right-handed,
// depth-[0, 1] ("RH_ZO") projections are exactly this project's clip space (NDC +y up).
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "graph/scene/scene.h"
#include "physics/vec3.h"
#include "shaders/include/gpu_struct.h"

namespace volgraph::physics {

using Mat4 = glm::dmat4;

// The scene's Vec3 (std::array) as GLM's vector and back.
inline glm::dvec3 vec(const Vec3& v) { return {v[0], v[1], v[2]}; }
inline Vec3 to_vec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// v / |v|: the rounding of the scene-side normalize below, which the camera's rays keep
// (the reference renderer's images are compared against stored ones); glm::normalize
// multiplies by inversesqrt instead.
inline glm::dvec3 unit(const glm::dvec3& v) { return v / glm::length(v); }

// Column-major floats for a uniform block's mat4 (GLSL's layout, and GLM's).
inline void to_floats(const Mat4& m, float* out) {
  const double* column_major = glm::value_ptr(m);
  for (size_t i = 0; i < 16; ++i) out[i] = float(column_major[i]);
}

// The same into a mat4 of a struct written once for GLSL and C++ (shaders/include/gpu_struct.h).
inline void to_floats(const Mat4& m, gpu::mat4& out) {
  const double* column_major = glm::value_ptr(m);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) out.columns[c][r] = float(column_major[c * 4 + r]);
  }
}

// (x, y, z, 1) → the transformed point divided by w.
inline Vec3 transform_point(const Mat4& t, const Vec3& p) {
  const glm::dvec4 h = t[0] * p[0] + t[1] * p[1] + t[2] * p[2] + t[3];
  return to_vec3(glm::dvec3(h) / h.w);
}

// World to view: the camera at the origin looking down −Z, +Y up.
inline Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up) {
  return glm::lookAtRH(vec(eye), vec(target), vec(up));
}

// View to clip, right-handed, depth in [0, 1]: z = −near → 0, z = −far → 1.
inline Mat4 perspective(double fov_y_deg, double aspect, double near, double far) {
  return glm::perspectiveRH_ZO(glm::radians(fov_y_deg), aspect, near, far);
}

// View to clip for a box [l, r] × [b, t] × [−near, −far], depth in [0, 1].
inline Mat4 orthographic(double l, double r, double b, double t, double near, double far) {
  return glm::orthoRH_ZO(l, r, b, t, near, far);
}

// Rotations by an angle in degrees about the X, Y and Z axes (counter-clockwise looking
// down the axis towards the origin), written out as GLSL would: columns.
inline Mat4 rotation_x(double deg) {
  const double c = std::cos(glm::radians(deg)), s = std::sin(glm::radians(deg));
  return Mat4(1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, 0, 0, 0, 1);
}
inline Mat4 rotation_y(double deg) {
  const double c = std::cos(glm::radians(deg)), s = std::sin(glm::radians(deg));
  return Mat4(c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1);
}
inline Mat4 rotation_z(double deg) {
  const double c = std::cos(glm::radians(deg)), s = std::sin(glm::radians(deg));
  return Mat4(c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
}

// Object to world: scale, then rotate about X, then Y, then Z, then translate.
inline Mat4 model_matrix(const Transform& t) {
  const Mat4 translate = glm::translate(Mat4(1), vec(t.translate)), scale = glm::scale(Mat4(1), vec(t.scale));
  return translate * rotation_z(t.rotate_deg[2]) * rotation_y(t.rotate_deg[1]) * rotation_x(t.rotate_deg[0]) * scale;
}

// The inverse transpose of a transform's 3×3 part (in a Mat4): it carries normals.
inline Mat4 normal_matrix(const Mat4& t) { return Mat4(glm::transpose(glm::inverse(glm::dmat3(t)))); }
// How much a transform stretches lengths, on average over directions of a volume: the
// cube root of its 3×3 determinant's magnitude (exact for a uniform scale). Carries a
// length given in an object's space (a glTF volume's thickness) into the world's.
inline double length_scale(const Mat4& t) { return std::cbrt(std::abs(glm::determinant(glm::dmat3(t)))); }

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
  const glm::dvec3 f = unit(vec(c.target) - vec(c.position));
  const glm::dvec3 s = unit(glm::cross(f, vec(c.up)));
  const glm::dvec3 u = glm::cross(s, f);
  return {c.position, to_vec3(f), to_vec3(s * (t * aspect)), to_vec3(u * t)};
}

inline Vec3 view_ray(const ViewRays& v, double ndc_x, double ndc_y) {
  return to_vec3(vec(v.forward) + (vec(v.right) * ndc_x + vec(v.up) * ndc_y));
}

// Where world point p lies in the view (shaders/include/view_rays.glsl `view_uvz`): the
// texture coordinate across the frame (u right, v down) and the view depth z (m).
struct ViewUvz {
  double u = 0, v = 0, z = 0;
};

inline ViewUvz view_uvz(const ViewRays& v, const Vec3& p) {
  const glm::dvec3 d = vec(p) - vec(v.position), right = vec(v.right), up = vec(v.up);
  const double z = glm::dot(d, vec(v.forward));
  const double along_x = glm::dot(d, right) / glm::dot(right, right), along_y = glm::dot(d, up) / glm::dot(up, up);
  const double inverse_z = 1.0 / std::max(z, 1e-20);
  return {0.5 + 0.5 * along_x * inverse_z, 0.5 - 0.5 * along_y * inverse_z, z};
}

// The direction (unit, world space) pixel (i, j) of a W × H frame looks along.
inline Vec3 pixel_ray(const Camera& c, uint32_t width, uint32_t height, double i, double j) {
  const double x = (i + 0.5) / width * 2 - 1, y = 1 - (j + 0.5) / height * 2;
  return to_vec3(unit(vec(view_ray(view_rays(c, double(width) / height), x, y))));
}

// The inverse of an affine transform (a model matrix): world to the object's space.
inline Mat4 inverse_affine(const Mat4& m) { return glm::affineInverse(m); }

// The inverse of any invertible 4×4 matrix (a projection too).
inline Mat4 inverse(const Mat4& m) { return glm::inverse(m); }

}  // namespace volgraph::physics
