#include "passes/shading/meshes.h"

#include <cmath>

namespace volgraph::shading {
namespace {

void add_vertex(Mesh& m, double x, double y, double z, double nx, double ny, double nz) {
  m.vertices.insert(m.vertices.end(), {float(x), float(y), float(z), float(nx), float(ny), float(nz)});
}

// A quad with corners origin, origin+u, origin+u+v, origin+v (counter-clockwise about n = u × v).
void add_quad(Mesh& m, const Vec3& o, const Vec3& u, const Vec3& v, const Vec3& n) {
  const uint32_t base = uint32_t(m.vertices.size() / 6);
  add_vertex(m, o[0], o[1], o[2], n[0], n[1], n[2]);
  add_vertex(m, o[0] + u[0], o[1] + u[1], o[2] + u[2], n[0], n[1], n[2]);
  add_vertex(m, o[0] + u[0] + v[0], o[1] + u[1] + v[1], o[2] + u[2] + v[2], n[0], n[1], n[2]);
  add_vertex(m, o[0] + v[0], o[1] + v[1], o[2] + v[2], n[0], n[1], n[2]);
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
      add_vertex(m, r * nx, r * ny, r * nz, nx, ny, nz);
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

}  // namespace volgraph::shading
