// glTF loading (tinygltf): the shipped sample models' triangle counts (../shared/assets/
// gltf/SOURCES.md), node transforms, unit normals, and a broken file named as such.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "passes/shading/gltf.h"

namespace volgraph::shading {
namespace {

const std::string kAssets = std::string(VOLGRAPH_SOURCE_DIR) + "/../shared/assets/gltf/";

TEST(Gltf, SuzanneHasItsTrianglesAndUnitNormals) {
  const GltfModel m = load_gltf(kAssets + "Suzanne/Suzanne.gltf");
  EXPECT_EQ(m.triangle_count(), 3936u);
  for (const GltfPrimitive& p : m.primitives) {
    for (size_t v = 0; v < p.vertices.size(); v += 6) {
      const double l = std::hypot(p.vertices[v + 3], p.vertices[v + 4], p.vertices[v + 5]);
      ASSERT_NEAR(l, 1.0, 1e-5);
    }
    EXPECT_TRUE(p.base_color_texture);  // Suzanne_BaseColor.png, not read yet
  }
}

TEST(Gltf, DamagedHelmetIsTurnedUprightByItsNode) {
  // The helmet's mesh is Z-up; its node's quaternion turns it Y-up: the model is taller
  // (Y) than deep (Z) once transformed.
  const GltfModel m = load_gltf(kAssets + "DamagedHelmet/DamagedHelmet.glb");
  EXPECT_EQ(m.triangle_count(), 15452u);
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  for (const GltfPrimitive& p : m.primitives) {
    for (size_t v = 0; v < p.vertices.size(); v += 6) {
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], double(p.vertices[v + size_t(k)]));
        hi[k] = std::max(hi[k], double(p.vertices[v + size_t(k)]));
      }
    }
  }
  EXPECT_GT(hi[1] - lo[1], 1.5);
  EXPECT_NEAR(hi[1] + lo[1], 0.0, 0.3);  // roughly centred
}

TEST(Gltf, ABrokenFileIsMalformed) {
  const auto path = std::filesystem::temp_directory_path() / ("volgraph_broken_" + std::to_string(::getpid()) + ".glb");
  std::ofstream(path) << "not a glTF";
  try {
    load_gltf(path.string());
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("malformed glTF"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace volgraph::shading
