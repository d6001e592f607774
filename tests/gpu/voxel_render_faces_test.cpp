// voxel_render's faces variant (passes/voxels/voxel_render.cpp) against its dda variant on both
// backends, one graph drawing the same voxelize grid three ways (dda, faces greedy, faces
// culled) over a scene whose floor cuts the voxels: where both hit, the rasterized quads' hit
// distance equals the ray cast's within 1e-4 relative and the colour within one fp16 step; the
// hit masks differ only at a few silhouette pixels (the rasterizer's coverage rule against the
// ray's); greedy and culled quads, covering the same faces, draw the same image; the pass draws
// two triangles a quad of the CPU twin's greedy mesh.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "passes/voxels/voxel_faces.h"
#include "passes/voxels/voxel_mesh.h"
#include "passes/voxels/voxel_shading.h"
#include "physics/camera.h"
#include "tests/gpu/backends.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr int kFacesResolution = 24;

// An off-centre sphere (its material transmits: the scene pass leaves it out of the depth)
// voxelized and drawn by the three; an opaque floor through it hides its lower voxels.
std::string faces_config() {
  const std::string cast_inputs = R"("inputs": { "voxels": "voxels.voxels", "grid": "voxels.grid", "depth": "lit.depth", "scene_color": "lit.color" })";
  return R"({ "output": { "size": [96, 80] },
  "scene": { "camera": { "position": [1.9, 1.6, 2.7], "target": [0.1, 0.1, 0], "fov_y_deg": 40, "far": 50 },
             "background": { "radiance": [0.05, 0.06, 0.08] },
             "materials": { "unseen": { "transmission": 1 }, "floor": { "albedo": [0.5, 0.5, 0.5] } },
             "lights": [ { "name": "sun", "type": "directional", "direction": [-0.3, -1, -0.5], "irradiance": [3, 3, 3] } ],
             "objects": [
               { "name": "ball", "shape": "sphere", "size": [0.7, 0.7, 0.7], "transform": { "translate": [0.1, 0.2, -0.05] }, "material": "unseen" },
               { "name": "floor", "shape": "plane", "size": [6, 1, 6], "material": "floor", "transform": { "translate": [0, 0.05, 0] } } ] },
  "graph": { "passes": [
      { "name": "lit", "type": "scene" },
      { "name": "voxels", "type": "voxelize", "params": { "object": 0, "resolution": )" +
         std::to_string(kFacesResolution) + R"( } },
      { "name": "dda", "type": "voxel_render", "variant": "dda", "params": { "albedo": [0.8, 0.55, 0.3] }, )" + cast_inputs + R"( },
      { "name": "greedy", "type": "voxel_render", "variant": "faces", "params": { "albedo": [0.8, 0.55, 0.3] }, )" + cast_inputs + R"( },
      { "name": "culled", "type": "voxel_render", "variant": "faces", "params": { "albedo": [0.8, 0.55, 0.3], "meshing": "culled" }, )" +
         cast_inputs + R"( } ],
    "outputs": ["dda.color", "dda.hit", "greedy.color", "greedy.hit", "culled.color", "culled.hit"] } })";
}

class VoxelFaces : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
    config_ = load_config_text("voxel_faces.json", faces_config(), registry_, {});
    Executor executor(device(), config_.graph, &config_.config.scene, {});
    executor.run_frame();
    for (size_t i = 0; i < 6; ++i) out_.push_back(executor.read_output(i));
    for (const SetupNote& note : executor.plan().setup_notes) notes_ += note.text + "\n";
  }
  PassRegistry registry_;
  LoadedConfig config_;
  std::vector<Texels> out_;  // dda colour, hit; greedy colour, hit; culled colour, hit
  std::string notes_;
};

// One fp16 step at the larger of the two values (10 mantissa bits).
bool within_one_half_step(float a, float b) { return std::abs(a - b) <= std::ldexp(std::max(std::abs(a), std::abs(b)), -10) + 1e-7f; }

// Pixels that see different faces where two meet: the ray's DDA and the rasterizer's coverage
// (and, between greedy and culled, the merged edge against the unit quads' T-junctions) round
// differently within a few 1e-6 m of a face's edge. Measured on this scene, both backends:
// dda against greedy 1 pixel, greedy against culled 2.
constexpr int kFaceEdgePixels = 3;

// Where both hit, the distance within 1e-4 relative; the colour within one fp16 step except at
// kFaceEdgePixels pixels at most (another face's colour, its distance still within 1e-4).
struct FaceImageAgreement {
  int both = 0, only_first = 0, only_second = 0, colour_differs = 0, bits_differ = 0;
  double worst_distance = 0;
};

FaceImageAgreement face_image_agreement(const Texels& first_colour, const Texels& first_hit, const Texels& second_colour, const Texels& second_hit) {
  FaceImageAgreement r;
  for (size_t p = 0; p < size_t(first_hit.width) * first_hit.height; ++p) {
    const float a = first_hit.rgba[4 * p], b = second_hit.rgba[4 * p];
    bool bits_differ = a != b, colour_differs = false;
    for (size_t k = 0; k < 3; ++k) {
      const float x = first_colour.rgba[4 * p + k], y = second_colour.rgba[4 * p + k];
      bits_differ = bits_differ || x != y;
      colour_differs = colour_differs || !within_one_half_step(x, y);
    }
    r.bits_differ += bits_differ;
    if ((a > 0) != (b > 0)) {
      ++(a > 0 ? r.only_first : r.only_second);
      continue;
    }
    r.colour_differs += colour_differs;
    if (a <= 0) continue;
    ++r.both;
    r.worst_distance = std::max(r.worst_distance, std::abs(double(b) - a) / a);
  }
  return r;
}

TEST_P(VoxelFaces, FacesDrawWhatTheDdaCasts) {
  ASSERT_TRUE(all_finite(out_[2]) && all_finite(out_[3]));
  const FaceImageAgreement r = face_image_agreement(out_[0], out_[1], out_[2], out_[3]);
  std::printf("dda against faces (greedy): %d pixels both hit, %d only dda, %d only faces; worst relative distance %.2e; "
              "%d pixels past one fp16 step in colour\n", r.both, r.only_first, r.only_second, r.worst_distance, r.colour_differs);
  EXPECT_GT(r.both, 1000);
  EXPECT_LE(r.worst_distance, 1e-4);
  EXPECT_LE(r.only_first + r.only_second, 4);  // silhouettes: the pixel centre's ray against the rasterizer's edge rule
  EXPECT_LE(r.colour_differs, kFaceEdgePixels);
}

// Every hit pixel of faces is one of the six faces' flat Lambert radiances by the C++ twin of
// the shading header (shaders/include/voxel_shading.h), within one fp16 step.
TEST_P(VoxelFaces, FacesAreShadedByTheSharedLambert) {
  const Scene& scene = config_.config.scene;
  const Vec3 sun = physics::normalize(scene.lights.at(0).direction);
  const glm::vec4 to_light(-float(sun[0]), -float(sun[1]), -float(sun[2]), 1.0f);
  std::vector<glm::vec3> radiances;
  for (int axis = 0; axis < 3; ++axis)
    for (const float sign : {-1.0f, 1.0f}) {
      glm::vec3 normal(0.0f);
      normal[axis] = sign;
      radiances.push_back(voxels::shading::voxel_face_radiance(normal, glm::vec3(0, 0, -1), to_light, glm::vec3(3.0f), glm::vec3(0.8f, 0.55f, 0.3f)));
    }
  int hits = 0, unmatched = 0;
  for (size_t p = 0; p < size_t(out_[3].width) * out_[3].height; ++p) {
    if (out_[3].rgba[4 * p] <= 0) continue;
    ++hits;
    const bool matched = std::any_of(radiances.begin(), radiances.end(), [&](const glm::vec3& l) {
      for (int k = 0; k < 3; ++k)
        if (!within_one_half_step(out_[2].rgba[4 * p + size_t(k)], l[k])) return false;
      return true;
    });
    unmatched += !matched;
  }
  std::printf("%d hit pixels, %d not one of the six faces' radiances\n", hits, unmatched);
  EXPECT_GT(hits, 1000);
  EXPECT_EQ(unmatched, 0);
}

TEST_P(VoxelFaces, GreedyAndCulledQuadsDrawTheSameImage) {
  const FaceImageAgreement r = face_image_agreement(out_[2], out_[3], out_[4], out_[5]);
  std::printf("greedy against culled: %d pixels both hit, %d only greedy, %d only culled; worst relative distance %.2e; "
              "%d pixels differ in any bit, %d past one fp16 step in colour\n",
              r.both, r.only_first, r.only_second, r.worst_distance, r.bits_differ, r.colour_differs);
  EXPECT_EQ(r.only_first + r.only_second, 0);
  EXPECT_LE(r.worst_distance, 1e-4);
  EXPECT_LE(r.bits_differ, kFaceEdgePixels);
}

// The pass draws the CPU twin's greedy quads (and culled ones), two triangles each.
TEST_P(VoxelFaces, DrawsTwoTrianglesPerQuadOfTheTwinsMesh) {
  const std::vector<voxels::Triangle> triangles = voxels::world_triangles(config_.config.scene, 0);
  const std::vector<uint8_t> solid =
      voxels::voxelize_on_cpu(voxels::grid_corners(triangles, voxels::grid_around(triangles, kFacesResolution)), kFacesResolution);
  const size_t greedy = voxels::greedy_faces(solid, kFacesResolution).size(), culled = voxels::culled_faces(solid, kFacesResolution).size();
  std::printf("%s", notes_.c_str());
  EXPECT_NE(notes_.find("drawing greedy: " + std::to_string(greedy) + " quads, " + std::to_string(2 * greedy) + " triangles"), std::string::npos);
  EXPECT_NE(notes_.find("drawing culled: " + std::to_string(culled) + " quads, " + std::to_string(2 * culled) + " triangles"), std::string::npos);
  const voxels::FaceTriangles mesh = voxels::face_triangles(voxels::greedy_faces(solid, kFacesResolution), glm::vec3(0), 1.0f);
  EXPECT_EQ(mesh.indices.size(), 6 * greedy);
}

INSTANTIATE_TEST_SUITE_P(Backends, VoxelFaces, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
