#include "passes/plumbing/meshes.h"

#include <cmath>

namespace volgraph::plumbing {

namespace {

void add_vertex(Mesh& m, const Vec3& p, const Vec3& n, double u, double v) {
  m.vertices.insert(m.vertices.end(), {float(p[0]), float(p[1]), float(p[2]), float(n[0]), float(n[1]), float(n[2]), float(u), float(v)});
}

Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

// A quad with corners origin, origin+u, origin+u+v, origin+v (counter-clockwise about
// n = u × v); the image spans it with its top row along the v end.
void add_quad(Mesh& m, const Vec3& o, const Vec3& u, const Vec3& v, const Vec3& n) {
  const uint32_t base = uint32_t(m.vertices.size() / kMeshVertexFloats);
  add_vertex(m, o, n, 0, 1);
  add_vertex(m, plus(o, u), n, 1, 1);
  add_vertex(m, plus(plus(o, u), v), n, 1, 0);
  add_vertex(m, plus(o, v), n, 0, 0);
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

Mesh box(const Vec3& s) {
  Mesh m;
  const double x = s[0] / 2, y = s[1] / 2, z = s[2] / 2;
  add_quad(m, {-x, -y, z}, {2 * x, 0, 0}, {0, 2 * y, 0}, {0, 0, 1});     // +Z
  add_quad(m, {x, -y, -z}, {-2 * x, 0, 0}, {0, 2 * y, 0}, {0, 0, -1});   // −Z
  add_quad(m, {x, -y, z}, {0, 0, -2 * z}, {0, 2 * y, 0}, {1, 0, 0});     // +X
  add_quad(m, {-x, -y, -z}, {0, 0, 2 * z}, {0, 2 * y, 0}, {-1, 0, 0});   // −X
  add_quad(m, {-x, y, z}, {2 * x, 0, 0}, {0, 0, -2 * z}, {0, 1, 0});     // +Y
  add_quad(m, {-x, -y, -z}, {2 * x, 0, 0}, {0, 0, 2 * z}, {0, -1, 0});   // −Y
  return m;
}

Mesh sphere(double r) {
  Mesh m;
  const int rings = 24, segments = 48;
  for (int i = 0; i <= rings; ++i) {
    const double theta = M_PI * i / rings;
    for (int j = 0; j <= segments; ++j) {
      const double phi = 2 * M_PI * j / segments;
      const double nx = std::sin(theta) * std::cos(phi), ny = std::cos(theta), nz = -std::sin(theta) * std::sin(phi);
      add_vertex(m, {r * nx, r * ny, r * nz}, {nx, ny, nz}, double(j) / segments, double(i) / rings);  // latitude-longitude
    }
  }
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = uint32_t(i * (segments + 1) + j), b = a + segments + 1;
      m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  return m;
}

}  // namespace

Mesh primitive_mesh(Shape shape, const Vec3& size) {
  switch (shape) {
    case Shape::plane: {
      Mesh m;
      add_quad(m, {-size[0] / 2, 0, size[2] / 2}, {size[0], 0, 0}, {0, 0, -size[2]}, {0, 1, 0});
      return m;
    }
    case Shape::box: return box(size);
    case Shape::sphere:
    case Shape::ellipsoid: return sphere(size[0]);
    case Shape::gltf: return {};
  }
  return {};
}

}  // namespace volgraph::plumbing
