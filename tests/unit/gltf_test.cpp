// glTF loading (tinygltf): the shipped sample models' triangle counts (../shared/assets/
// gltf/SOURCES.md), node transforms, unit normals, a broken file named as such, every model
// under ../shared/assets/gltf/ loading with what it uses and volgraph does not draw named, and
// a file requiring an unsupported extension refused with the extension's name.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "passes/plumbing/gltf.h"
#include "passes/plumbing/meshes.h"
#include "tests/support/source_dir.h"

namespace volgraph::plumbing {

namespace {

const std::string kAssets = std::string(::volgraph::testing::source_dir()) + "/../shared/assets/gltf/";

TEST(Gltf, SuzanneHasItsTrianglesAndUnitNormals) {
  const GltfModel m = load_gltf(kAssets + "Suzanne/Suzanne.gltf");
  EXPECT_EQ(m.triangle_count(), 3936u);
  for (const GltfPrimitive& p : m.primitives) {
    for (size_t v = 0; v < p.vertices.size(); v += kMeshVertexFloats) {
      const double l = std::hypot(p.vertices[v + 3], p.vertices[v + 4], p.vertices[v + 5]);
      ASSERT_NEAR(l, 1.0, 1e-5);
    }
    ASSERT_TRUE(p.base_color_texture);  // Suzanne_BaseColor.png, a file beside the .gltf
    EXPECT_FALSE(p.emissive_texture);
  }
  ASSERT_EQ(m.images.size(), 2u);  // base colour and metallic-roughness
  const Rgba8Image base = m.images[size_t(m.primitives[0].base_color_texture.image)].decode();
  EXPECT_EQ(base.width, 1024u);  // file(1): PNG image data, 1024 x 1024
  EXPECT_EQ(base.height, 1024u);
}

TEST(Gltf, DamagedHelmetHasItsTexturesAndCoordinatesInsideThem) {
  const GltfModel m = load_gltf(kAssets + "DamagedHelmet/DamagedHelmet.glb");
  ASSERT_EQ(m.primitives.size(), 1u);
  const GltfPrimitive& p = m.primitives[0];
  ASSERT_TRUE(p.base_color_texture);
  ASSERT_TRUE(p.emissive_texture);
  EXPECT_NE(p.base_color_texture.image, p.emissive_texture.image);
  EXPECT_EQ(p.emissive, (Vec3{1, 1, 1}));
  double lo = 1e9, hi = -1e9;
  for (size_t v = 0; v < p.vertices.size(); v += kMeshVertexFloats) {
    lo = std::min({lo, double(p.vertices[v + 6]), double(p.vertices[v + 7])});
    hi = std::max({hi, double(p.vertices[v + 6]), double(p.vertices[v + 7])});
  }
  // The atlas spans [0, 2) in v: the helmet relies on its sampler's default repeat wrap.
  EXPECT_GE(lo, 0.0);
  EXPECT_GT(hi, 1.5);
  EXPECT_LT(hi, 2.0);
  EXPECT_EQ(p.base_color_texture.wrap.u, rhi::AddressMode::repeat);
  EXPECT_EQ(p.base_color_texture.wrap.v, rhi::AddressMode::repeat);
  const Rgba8Image emissive = m.images[size_t(p.emissive_texture.image)].decode();
  EXPECT_EQ(emissive.texels.size(), size_t(emissive.width) * emissive.height * 4);
}

TEST(Gltf, AnImageThatIsNotOneIsMalformed) {
  // A .gltf whose image is a text file: the load fails naming the image.
  const auto dir = std::filesystem::temp_directory_path() / ("volgraph_badimage_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kAssets + "Suzanne/Suzanne.gltf", dir / "Suzanne.gltf");
  std::filesystem::copy_file(kAssets + "Suzanne/Suzanne.bin", dir / "Suzanne.bin");
  std::filesystem::copy_file(kAssets + "Suzanne/Suzanne_MetallicRoughness.png", dir / "Suzanne_MetallicRoughness.png");
  std::ofstream(dir / "Suzanne_BaseColor.png") << "this is text, not a PNG";
  try {
    load_gltf((dir / "Suzanne.gltf").string());
    ADD_FAILURE() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not an image"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(Gltf, DamagedHelmetIsTurnedUprightByItsNode) {
  // The helmet's mesh is Z-up; its node's quaternion turns it Y-up: the model is taller
  // (Y) than deep (Z) once transformed.
  const GltfModel m = load_gltf(kAssets + "DamagedHelmet/DamagedHelmet.glb");
  EXPECT_EQ(m.triangle_count(), 15452u);
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  for (const GltfPrimitive& p : m.primitives) {
    for (size_t v = 0; v < p.vertices.size(); v += kMeshVertexFloats) {
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

// Every model in the shared assets loads: triangles with finite positions; the transmission
// samples have translucent primitives and no model is drawn opaque for its transmission;
// what volgraph does not draw is named.
TEST(Gltf, EverySharedModelLoadsAndNamesWhatItIgnores) {
  int models = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kAssets)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".glb" && ext != ".gltf") continue;
    ++models;
    const std::string name = e.path().filename().string();
    const GltfModel m = load_gltf(e.path().string());
    EXPECT_GT(m.triangle_count(), 0u) << name;
    for (const GltfPrimitive& p : m.primitives) {
      for (float v : p.vertices) ASSERT_TRUE(std::isfinite(v)) << name;
    }
    const bool transmissive = name == "AttenuationTest.glb" || name == "GlassVaseFlowers.glb" ||
                              name == "TransmissionTest.glb" || name == "GlassBrokenWindow.glb";
    const bool translucent =
        std::any_of(m.primitives.begin(), m.primitives.end(), [](const GltfPrimitive& p) { return p.translucency.translucent(); });
    EXPECT_EQ(translucent, transmissive) << name;
    for (const std::string& note : m.ignored) EXPECT_EQ(note.find("drawn opaque"), std::string::npos) << name << ": " << note;
    if (name == "zdm2.glb" || name == "Suzanne.gltf") EXPECT_TRUE(m.ignored.empty()) << name << ": " << m.ignored.front();
  }
  EXPECT_EQ(models, 9);  // ../shared/assets/gltf/SOURCES.md lists nine models
}

TEST(Gltf, ARequiredExtensionVolgraphLacksIsRefusedByName) {
  const auto path = std::filesystem::temp_directory_path() / ("volgraph_draco_" + std::to_string(::getpid()) + ".gltf");
  std::ofstream(path) << R"({ "asset": { "version": "2.0" }, "extensionsUsed": ["KHR_draco_mesh_compression"],
    "extensionsRequired": ["KHR_draco_mesh_compression"], "scenes": [ { "nodes": [] } ], "scene": 0 })";
  try {
    load_gltf(path.string());
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("requires the glTF extension KHR_draco_mesh_compression"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace volgraph::plumbing
