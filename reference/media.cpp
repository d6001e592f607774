#include "reference/media.h"

#include <algorithm>
#include <cmath>

#include "passes/shading/media.h"
#include "passes/shading/phase.h"

namespace volgraph::reference {
namespace {

using shading::Mat4;

constexpr double kInfiniteDepth = 1e300;
// e^(−this) is below double's resolution of 1: height fog beyond it adds nothing.
constexpr double kNegligibleExponent = 50;

// World to local of an affine transform: the inverse 3×3 is the transpose of the normal
// matrix (its inverse transpose), the translation follows.
Mat4 affine_inverse(const Mat4& model) {
  const Mat4 n = shading::normal_matrix(model);
  Mat4 inv = Mat4::identity();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) inv(row, col) = n(col, row);
  }
  for (int row = 0; row < 3; ++row) {
    inv(row, 3) = -(inv(row, 0) * model(0, 3) + inv(row, 1) * model(1, 3) + inv(row, 2) * model(2, 3));
  }
  return inv;
}

Vec3 transform_vector(const Mat4& m, const Vec3& v) {
  return {m(0, 0) * v[0] + m(0, 1) * v[1] + m(0, 2) * v[2], m(1, 0) * v[0] + m(1, 1) * v[1] + m(1, 2) * v[2],
          m(2, 0) * v[0] + m(2, 1) * v[1] + m(2, 2) * v[2]};
}

Vec3 sigma_t(const Medium& m) { return shading::add(m.sigma_s, m.sigma_a); }

std::optional<Interval> box_interval(const Vec3& o, const Vec3& d) {
  double enter = -std::numeric_limits<double>::infinity(), exit = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (std::abs(o[k]) > 0.5) return std::nullopt;
      continue;
    }
    double a = (-0.5 - o[k]) / d[k], b = (0.5 - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    enter = std::max(enter, a);
    exit = std::min(exit, b);
  }
  if (enter > exit) return std::nullopt;
  return Interval{enter, exit};
}

// |o + t·d|² = 1, roots by the cancellation-free quadratic formula (Press et al.,
// Numerical Recipes, 3rd ed., eq. 5.6.4–5.6.5).
std::optional<Interval> ball_interval(const Vec3& o, const Vec3& d) {
  const double a = shading::dot(d, d), b = 2 * shading::dot(o, d), c = shading::dot(o, o) - 1;
  const double discriminant = b * b - 4 * a * c;
  if (a == 0 || discriminant < 0) return std::nullopt;
  const double q = -(b + std::copysign(std::sqrt(discriminant), b)) / 2;
  if (q == 0) return Interval{0, 0};
  const double r1 = q / a, r2 = c / q;
  return Interval{std::min(r1, r2), std::max(r1, r2)};
}

// The volume's size as a scale of the unit shape: box edges, a sphere's radius, an
// ellipsoid's radii.
Mat4 unit_shape_to_volume(const MediumVolume& v) {
  Mat4 scale = Mat4::identity();
  for (int k = 0; k < 3; ++k) scale(k, k) = v.shape == Shape::sphere ? v.size[0] : v.size[size_t(k)];
  return scale;
}

}  // namespace

std::string unsupported(const Media& media) {
  for (size_t i = 0; i < media.volumes.size(); ++i) {
    if (media.volumes[i].noise.octaves > 0) {
      return "volume " + std::to_string(i) + " has noise: heterogeneous media are not in the reference yet";
    }
  }
  return "";
}

Vec3 transmittance_of(const Vec3& optical_depth) {
  return {shading::transmittance(optical_depth[0], 1.0), shading::transmittance(optical_depth[1], 1.0),
          shading::transmittance(optical_depth[2], 1.0)};
}

std::optional<Interval> unit_shape_interval(Shape shape, const Vec3& origin, const Vec3& direction) {
  return shape == Shape::box ? box_interval(origin, direction) : ball_interval(origin, direction);
}

SceneMedia::SceneMedia(const Media& media) : fog_(media.fog), height_fog_(media.height_fog) {
  for (const MediumVolume& v : media.volumes) {
    const Mat4 model = shading::model_matrix(v.transform) * unit_shape_to_volume(v);
    volumes_.push_back({v.shape, model, affine_inverse(model), v.medium});
  }
}

std::optional<Interval> SceneMedia::volume_interval(const Volume& v, const Vec3& origin, const Vec3& direction) const {
  return unit_shape_interval(v.shape, shading::transform_point(v.inverse, origin), transform_vector(v.inverse, direction));
}

void SceneMedia::visit(const Vec3& p, const std::function<void(const Medium&, double)>& medium_with_density) const {
  if (fog_) medium_with_density(*fog_, 1);
  if (height_fog_) {
    medium_with_density(height_fog_->medium, std::exp(-height_fog_->falloff * (p[1] - height_fog_->base_height)));
  }
  for (const Volume& v : volumes_) {
    const Vec3 local = shading::transform_point(v.inverse, p);
    const bool inside = v.shape == Shape::box ? std::max({std::abs(local[0]), std::abs(local[1]), std::abs(local[2])}) <= 0.5
                                              : shading::dot(local, local) <= 1;
    if (inside) medium_with_density(v.medium, 1);
  }
}

MediumPoint SceneMedia::at(const Vec3& p) const {
  MediumPoint out;
  visit(p, [&out](const Medium& m, double density) {
    for (size_t c = 0; c < 3; ++c) {
      out.sigma_s[c] += density * m.sigma_s[c];
      out.sigma_t[c] += density * (m.sigma_s[c] + m.sigma_a[c]);
      out.emission[c] += density * m.emission[c];
    }
  });
  return out;
}

Vec3 SceneMedia::scattering(const Vec3& p, double cos_theta) const {
  Vec3 out{0, 0, 0};
  visit(p, [&](const Medium& m, double density) {
    const double phase = m.g == 0 ? shading::phase_isotropic<double>() : shading::phase_hg(m.g, cos_theta);
    for (size_t c = 0; c < 3; ++c) out[c] += density * m.sigma_s[c] * phase;
  });
  return out;
}

std::vector<double> SceneMedia::boundaries(const Vec3& origin, const Vec3& direction, double t0, double t1) const {
  std::vector<double> out;
  for (const Volume& v : volumes_) {
    const std::optional<Interval> i = volume_interval(v, origin, direction);
    if (!i) continue;
    for (double t : {i->enter, i->exit}) {
      if (t > t0 && t < t1) out.push_back(t);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Vec3 SceneMedia::volumes_optical_depth(const Vec3& origin, const Vec3& direction, double t0, double t1) const {
  Vec3 depth{0, 0, 0};
  for (const Volume& v : volumes_) {
    const std::optional<Interval> i = volume_interval(v, origin, direction);
    if (!i) continue;
    const double inside = std::min(t1, i->exit) - std::max(t0, i->enter);
    if (inside > 0) depth = shading::add(depth, shading::scaled(sigma_t(v.medium), inside));
  }
  return depth;
}

Vec3 SceneMedia::height_fog_optical_depth(double origin_y, double direction_y, double length) const {
  if (!height_fog_) return {0, 0, 0};
  const HeightFog& h = *height_fog_;
  const Vec3 base = sigma_t(h.medium);
  Vec3 depth;
  for (size_t c = 0; c < 3; ++c) {
    depth[c] = shading::height_fog_optical_depth(base[c], h.falloff, h.base_height, origin_y, direction_y, length);
  }
  return depth;
}

Vec3 SceneMedia::optical_depth(const Vec3& origin, const Vec3& direction, double t0, double t1) const {
  if (!(t1 > t0)) return {0, 0, 0};
  Vec3 depth = volumes_optical_depth(origin, direction, t0, t1);
  if (fog_) depth = shading::add(depth, shading::scaled(sigma_t(*fog_), t1 - t0));
  return shading::add(depth, height_fog_optical_depth(origin[1] + t0 * direction[1], direction[1], t1 - t0));
}

Vec3 SceneMedia::optical_depth_to_infinity(const Vec3& origin, const Vec3& direction) const {
  Vec3 depth = volumes_optical_depth(origin, direction, 0, std::numeric_limits<double>::infinity());
  if (!height_fog_) return depth;
  const Vec3 base = sigma_t(height_fog_->medium);
  if (direction[1] <= 0) {  // down (or level) forever through ever denser fog
    for (size_t c = 0; c < 3; ++c) depth[c] += base[c] > 0 ? kInfiniteDepth : 0;
    return depth;
  }
  // Far enough that the rest is below e^(−kNegligibleExponent) of what came before.
  const double length = kNegligibleExponent / (height_fog_->falloff * direction[1]);
  return shading::add(depth, height_fog_optical_depth(origin[1], direction[1], length));
}

}  // namespace volgraph::reference
