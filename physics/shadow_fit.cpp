// Shadow-map projections fitted to the receivers a camera sees and to the scene's casters
// (physics/shadow_fit.h). Stable fitting after Valient, "Stable rendering of
// cascaded shadow maps" (ShaderX6, 2007) and MSDN "Common techniques to improve shadow
// depth maps": a window whose size moves in steps and whose origin sits on whole texels.
#include "physics/shadow_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace volgraph::physics {
namespace {

constexpr double kMinWindow = 1e-3;  // metres: the narrowest window side (receivers seen edge-on)
constexpr double kSizeSteps = 4;     // window sides are whole powers of 2^(1/4) metres

std::array<Vec3, 8> box_corners(const Box& b) {
  std::array<Vec3, 8> corners;
  for (size_t i = 0; i < 8; ++i) {
    corners[i] = {i & 1 ? b.max[0] : b.min[0], i & 2 ? b.max[1] : b.min[1], i & 4 ? b.max[2] : b.min[2]};
  }
  return corners;
}

Vec3 box_centre(const Box& b) { return to_vec3((vec(b.min) + vec(b.max)) * 0.5); }

// The box's diagonal length.
double diagonal(const Box& b) { return glm::length(vec(b.max) - vec(b.min)); }

// The 12 edges of a hexahedron whose corner i has the bits (x, y, z): corners one bit apart.
std::array<std::array<size_t, 2>, 12> hexahedron_edges() {
  std::array<std::array<size_t, 2>, 12> edges;
  size_t n = 0;
  for (size_t i = 0; i < 8; ++i) {
    for (size_t bit = 1; bit < 8; bit <<= 1) {
      if (!(i & bit)) edges[n++] = {i, i | bit};
    }
  }
  return edges;
}

struct Plane {
  Vec3 normal;  // unit, toward the inside
  double offset = 0;
};

double signed_distance(const Plane& plane, const Vec3& p) { return glm::dot(vec(plane.normal), vec(p)) - plane.offset; }

// The first three corners of the face where corner bit `bit` equals `side` (not in a line
// on a frustum slice).
std::array<size_t, 3> face_corners(size_t bit, size_t side) {
  std::array<size_t, 3> face{};
  size_t n = 0;
  for (size_t i = 0; i < 8 && n < 3; ++i) {
    if ((i & bit) == side) face[n++] = i;
  }
  return face;
}

// The 6 face planes of a hexahedron with planar faces (a frustum slice), facing inward.
std::array<Plane, 6> hexahedron_planes(const std::array<Vec3, 8>& corners) {
  glm::dvec3 centroid(0);
  for (const Vec3& c : corners) centroid += vec(c) * (1.0 / 8);
  std::array<Plane, 6> planes;
  size_t n = 0;
  for (size_t bit = 1; bit < 8; bit <<= 1) {
    for (const size_t side : {size_t{0}, bit}) {
      const std::array<size_t, 3> face = face_corners(bit, side);
      const glm::dvec3 a = vec(corners[face[0]]);
      glm::dvec3 normal = unit(glm::cross(vec(corners[face[1]]) - a, vec(corners[face[2]]) - a));
      if (glm::dot(normal, centroid - a) < 0) normal = -normal;
      planes[n++] = {to_vec3(normal), glm::dot(normal, a)};
    }
  }
  return planes;
}

// Where the segment a→b crosses a plane, from the ends' signed distances (opposite signs).
Vec3 crossing(const Vec3& a, const Vec3& b, double distance_a, double distance_b) {
  return to_vec3(vec(a) + (vec(b) - vec(a)) * (distance_a / (distance_a - distance_b)));
}

// The region a frustum slice and a box share, with a tolerance for points on its faces.
struct SharedRegion {
  const Box& box;
  std::array<Plane, 6> slice_planes;
  double tolerance = 0;

  bool contains(const Vec3& p) const {
    for (size_t axis = 0; axis < 3; ++axis) {
      if (p[axis] < box.min[axis] - tolerance || p[axis] > box.max[axis] + tolerance) return false;
    }
    return std::all_of(slice_planes.begin(), slice_planes.end(),
                       [&](const Plane& plane) { return signed_distance(plane, p) >= -tolerance; });
  }
};

// Where the slice's edges cross the box's faces, inside both.
void add_slice_edge_crossings(const std::array<Vec3, 8>& slice, const SharedRegion& region, std::vector<Vec3>& out) {
  for (const auto& [i, j] : hexahedron_edges()) {
    for (size_t axis = 0; axis < 3; ++axis) {
      for (const double face : {region.box.min[axis], region.box.max[axis]}) {
        const double da = slice[i][axis] - face, db = slice[j][axis] - face;
        if (da * db >= 0) continue;
        const Vec3 p = crossing(slice[i], slice[j], da, db);
        if (region.contains(p)) out.push_back(p);
      }
    }
  }
}

// Where the box's edges cross the slice's faces, inside both.
void add_box_edge_crossings(const std::array<Vec3, 8>& box, const SharedRegion& region, std::vector<Vec3>& out) {
  for (const auto& [i, j] : hexahedron_edges()) {
    for (const Plane& plane : region.slice_planes) {
      const double da = signed_distance(plane, box[i]), db = signed_distance(plane, box[j]);
      if (da * db >= 0) continue;
      const Vec3 p = crossing(box[i], box[j], da, db);
      if (region.contains(p)) out.push_back(p);
    }
  }
}

// Axis-aligned bounds of points in some frame.
struct Bounds3 {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
};

Bounds3 bounds_in(const Mat4& frame, std::span<const Vec3> points) {
  Bounds3 b;
  for (const Vec3& world : points) {
    const Vec3 p = transform_point(frame, world);
    for (size_t axis = 0; axis < 3; ++axis) {
      b.lo[axis] = std::min(b.lo[axis], p[axis]);
      b.hi[axis] = std::max(b.hi[axis], p[axis]);
    }
  }
  return b;
}

// World to a light's view at `eye`, looking along `direction` (unit).
Mat4 light_view(const Vec3& eye, const Vec3& direction) {
  const Vec3 up = std::abs(direction[1]) > 0.99 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
  return look_at(eye, to_vec3(vec(eye) + vec(direction)), up);
}

double tan_half_fov(const Camera& camera) { return std::tan(camera.fov_y_deg * M_PI / 360.0); }

// Diameter of the smallest sphere around a frustum slice: centred on the axis where its
// near and far corners are equally far (at most on the far plane). It depends on the lens
// and the depths only, not on where the camera stands or looks.
double slice_sphere_diameter(const Camera& camera, double aspect, const DepthRange& depths) {
  const double t = tan_half_fov(camera);
  const double spread = t * t * (1 + aspect * aspect);  // squared half-diagonal per squared metre of depth
  const double n = depths.near, f = depths.far;
  const double centre = std::min((n + f) * (1 + spread) / 2, f);
  const double near_r2 = (centre - n) * (centre - n) + n * n * spread;
  const double far_r2 = (f - centre) * (f - centre) + f * f * spread;
  return 2 * std::sqrt(std::max(near_r2, far_r2));
}

// Depths along the light over the scene's whole box — casters outside the camera's view
// still shadow what it sees — padded so float rounding keeps every caster inside [0, 1].
void fit_depths(const Bounds3& scene_in_light, double scene_diagonal, OrthoFit& fit) {
  const double nearest = -scene_in_light.hi[2], farthest = -scene_in_light.lo[2];  // the view looks down −z
  const double pad = 0.01 * (farthest - nearest) + 1e-3 * scene_diagonal + kMinWindow;
  fit.near = nearest - pad;
  fit.far = farthest + pad;
}

// Stable size: the receivers' extent stepped up to a power of 2^(1/4), at most the slice's bounding sphere (turn-invariant).
double window_side(double extent, double sphere_diameter, uint32_t texels) {
  const double slack = double(texels) / (texels - 1);  // room for the snapped origin up to a texel below the receivers
  const double stepped = std::exp2(std::ceil(kSizeSteps * std::log2(std::max(extent, kMinWindow) * slack)) / kSizeSteps);
  return std::min(stepped, std::max(sphere_diameter, kMinWindow) * slack);
}

struct Interval {
  double lo = 0;
  double hi = 0;
};

// Texel snapping (Valient 2007; MSDN "Common techniques to improve shadow depth maps"):
// the window starts on a whole texel of the light's fixed grid, so a moving camera
// shifts it by whole texels and the shadow's edges do not shimmer.
Interval snapped_window(double receivers_lo, double side, uint32_t texels) {
  const double texel = side / texels;
  const double origin = std::floor(receivers_lo / texel) * texel;
  return {origin, origin + side};
}

}  // namespace

DepthRange receiver_depths(const Camera& camera, const Box& scene, double distance) {
  if (distance > 0) return {camera.near, std::min(camera.far, distance)};
  const glm::dvec3 forward = unit(vec(camera.target) - vec(camera.position));
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Vec3& corner : box_corners(scene)) {
    deepest = std::max(deepest, glm::dot(vec(corner) - vec(camera.position), forward));
  }
  return {camera.near, std::min(camera.far, deepest)};
}

std::array<Vec3, 8> frustum_slice_corners(const Camera& camera, double aspect, const DepthRange& depths) {
  const glm::dvec3 forward = unit(vec(camera.target) - vec(camera.position));
  const glm::dvec3 side = unit(glm::cross(forward, vec(camera.up)));
  const glm::dvec3 up = glm::cross(side, forward);
  const double t = tan_half_fov(camera);
  std::array<Vec3, 8> corners;
  for (size_t i = 0; i < 8; ++i) {
    const double x = i & 1 ? 1 : -1, y = i & 2 ? 1 : -1, depth = i & 4 ? depths.far : depths.near;
    const glm::dvec3 ray = forward + (side * (x * t * aspect) + up * (y * t));
    corners[i] = to_vec3(vec(camera.position) + ray * depth);
  }
  return corners;
}

// The vertices of the intersection of two convex solids: each one's corners inside the
// other and each one's edges crossing the other's faces.
std::vector<Vec3> slice_box_intersection(const std::array<Vec3, 8>& slice, const Box& box) {
  const std::array<Vec3, 8> corners = box_corners(box);
  const double scale = diagonal(box) + glm::length(vec(slice[7]) - vec(slice[0]));
  const SharedRegion region{box, hexahedron_planes(slice), 1e-9 * scale};
  std::vector<Vec3> vertices;
  for (const Vec3& p : slice) {
    if (region.contains(p)) vertices.push_back(p);
  }
  for (const Vec3& p : corners) {
    if (region.contains(p)) vertices.push_back(p);
  }
  add_slice_edge_crossings(slice, region, vertices);
  add_box_edge_crossings(corners, region, vertices);
  return vertices;
}

OrthoFit fit_directional_to_scene(const Vec3& direction, const Box& scene) {
  const Vec3 dir = to_vec3(unit(vec(direction)));
  const Vec3 centre = box_centre(scene);
  const double radius = std::max(diagonal(scene) / 2, 1e-3);
  OrthoFit fit;
  fit.view = light_view(to_vec3(vec(centre) - vec(dir) * (2 * radius)), dir);
  fit.left = fit.bottom = -radius;
  fit.right = fit.top = radius;
  fit.near = 0.5 * radius;
  fit.far = 3.5 * radius;
  return fit;
}

OrthoFit fit_directional_to_camera(const Vec3& direction, const Box& scene, const ReceiverView& view) {
  const DepthRange depths = receiver_depths(view.camera, scene, view.distance);
  if (depths.far <= depths.near) return fit_directional_to_scene(direction, scene);
  const std::vector<Vec3> receivers =
      slice_box_intersection(frustum_slice_corners(view.camera, view.aspect, depths), scene);
  if (receivers.empty()) return fit_directional_to_scene(direction, scene);

  OrthoFit fit;
  fit.view = light_view(box_centre(scene), to_vec3(unit(vec(direction))));  // fixed while the camera moves: a stable texel grid
  fit_depths(bounds_in(fit.view, box_corners(scene)), diagonal(scene), fit);
  // The receivers lie inside the box, so their bounds are already within the box's.
  const Bounds3 seen = bounds_in(fit.view, receivers);
  const double diameter = slice_sphere_diameter(view.camera, view.aspect, depths);
  const uint32_t wide = std::max(view.texels_wide, 2u), high = std::max(view.texels_high, 2u);
  const Interval x = snapped_window(seen.lo[0], window_side(seen.hi[0] - seen.lo[0], diameter, wide), wide);
  const Interval y = snapped_window(seen.lo[1], window_side(seen.hi[1] - seen.lo[1], diameter, high), high);
  fit.left = x.lo;
  fit.right = x.hi;
  fit.bottom = y.lo;
  fit.top = y.hi;
  return fit;
}

Mat4 fit_spot(const Light& light, const Box& scene) {
  const Mat4 view = light_view(light.position, to_vec3(unit(vec(light.direction))));
  const Bounds3 box = bounds_in(view, box_corners(scene));
  const double nearest = -box.hi[2], deepest = -box.lo[2];  // depths along the spot's axis
  const double far = std::max(1.01 * deepest, 0.1);
  // Near stays close to the light: depth_bias is in normalised depth, and a near plane at the
  // scene would shrink its size in metres (acne); it still comes closer for a caster nearer than that.
  const double close = std::min(0.05, far / 100);
  const double near = nearest > 0 ? std::max(std::min(close, 0.99 * nearest), far * 1e-6) : close;
  return perspective(2 * light.outer_cone_deg, 1.0, near, far) * view;
}

Box including(const Box& box, std::span<const Vec3> points) {
  Box grown = box;
  for (const Vec3& p : points) {
    for (size_t a = 0; a < 3; ++a) {
      grown.min[a] = std::min(grown.min[a], p[a]);
      grown.max[a] = std::max(grown.max[a], p[a]);
    }
  }
  return grown;
}

Box volume_bounds(const MediumVolume& volume) {
  const double r = volume.size[0];
  const Vec3 half = volume.shape == Shape::box ? to_vec3(vec(volume.size) * 0.5) : volume.shape == Shape::sphere ? Vec3{r, r, r} : volume.size;
  const Mat4 to_world = model_matrix(volume.transform);
  std::array<Vec3, 8> corners;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 local{corner & 1 ? half[0] : -half[0], corner & 2 ? half[1] : -half[1], corner & 4 ? half[2] : -half[2]};
    corners[size_t(corner)] = transform_point(to_world, local);
  }
  return including(Box{corners[0], corners[0]}, corners);
}

std::optional<Box> shadowed_bounds(const std::optional<Box>& geometry, const Media& media) {
  std::optional<Box> bounds = geometry;
  for (const MediumVolume& volume : media.volumes) {
    const Box v = volume_bounds(volume);
    const std::array<Vec3, 2> extremes{v.min, v.max};
    bounds = bounds ? including(*bounds, extremes) : v;
  }
  return bounds;
}

}  // namespace volgraph::physics
