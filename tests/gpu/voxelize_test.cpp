// voxelize and voxel_render (passes/voxels/) on both backends: the GPU's voxels equal the CPU
// twin's (passes/voxels/voxel_mesh.h, the same shaders/include/voxel_overlap.h) bit for bit for
// a box and a sphere; a grid-filling box sets exactly its shell, 6n² − 12n + 8; the DDA's hit
// distance is the analytic distance to the face it enters; no NaN with the camera in the grid.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "passes/voxels/voxel_mesh.h"
#include "physics/camera.h"
#include "tests/gpu/backends.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kVoxelFrame = 64;

// One object (`object`: its JSON), voxelized at `resolution`, ray cast over an empty scene: the
// object's material transmits, so the scene pass (opaque surfaces) leaves it out of the depth.
std::string voxel_config(const std::string& object, int resolution, const std::string& camera_position) {
  return R"({ "output": { "size": [64, 64] },
  "scene": { "camera": { "position": )" + camera_position + R"(, "target": [0.1, 0.2, 0], "fov_y_deg": 45, "far": 50 },
             "background": { "radiance": [0, 0, 0] },
             "materials": { "unseen": { "transmission": 1 } },
             "lights": [ { "name": "sun", "type": "directional", "direction": [-0.3, -1, -0.5], "irradiance": [3, 3, 3] } ],
             "objects": [ )" + object + R"( ] },
  "graph": { "passes": [
      { "name": "voxels", "type": "voxelize", "params": { "object": 0, "resolution": )" + std::to_string(resolution) + R"( } },
      { "name": "empty", "type": "scene" },
      { "name": "cast", "type": "voxel_render", "variant": "dda",
        "inputs": { "voxels": "voxels.voxels", "grid": "voxels.grid", "depth": "empty.depth", "scene_color": "empty.color" } } ],
    "outputs": ["voxels.voxels", "cast.color", "cast.hit"] } })";
}

const char* kVoxelBox = R"({ "name": "box", "shape": "box", "size": [2, 2, 2], "material": "unseen" })";
const char* kVoxelSphere = R"({ "name": "ball", "shape": "sphere", "size": [0.7, 0.7, 0.7], "transform": { "translate": [0.1, 0.2, -0.05] }, "material": "unseen" })";

class Voxelize : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  std::vector<Texels> render(const std::string& object, int resolution, const std::string& camera = "[2.5, 3, 4]") {
    config_ = load_config_text("voxelize.json", voxel_config(object, resolution, camera), registry_, {});
    Executor executor(device(), config_.graph, &config_.config.scene, {});
    executor.run_frame();
    return {executor.read_output(0), executor.read_output(1), executor.read_output(2)};
  }
  std::vector<uint8_t> twin(int resolution) const {
    const std::vector<voxels::Triangle> triangles = voxels::world_triangles(config_.config.scene, 0);
    return voxels::voxelize_on_cpu(voxels::grid_corners(triangles, voxels::grid_around(triangles, resolution)), resolution);
  }
  PassRegistry registry_;
  LoadedConfig config_;
};

// The GPU's r channel (0 or 1) against the twin's, voxel by voxel (x fastest, slices in z).
TEST_P(Voxelize, GpuVoxelsEqualTheCpuTwinsBitForBit) {
  for (const char* object : {kVoxelBox, kVoxelSphere})
    for (const int n : {16, 32}) {
      const std::string shape = object == kVoxelBox ? "box" : "sphere";
      const Texels gpu = render(object, n)[0];
      const std::vector<uint8_t> cpu = twin(n);
      ASSERT_EQ(size_t(gpu.width) * gpu.height * gpu.depth, cpu.size());
      size_t differ = 0, set = 0;
      for (size_t i = 0; i < cpu.size(); ++i) {
        differ += (gpu.rgba[4 * i] > 0.5f) != (cpu[i] == 1);
        set += cpu[i];
      }
      std::printf("%s at %d³: %zu voxels set, %zu differ\n", shape.c_str(), n, set, differ);
      EXPECT_GT(set, 0u);
      EXPECT_EQ(differ, 0u) << shape << " at " << n;
    }
}

// A 2 m box fills its grid exactly (faces on the grid's faces): the outer layer is set.
TEST_P(Voxelize, AGridFillingBoxSetsExactlyItsShell) {
  for (const int n : {8, 16}) {
    const Texels gpu = render(kVoxelBox, n)[0];
    size_t set = 0;
    for (size_t i = 0; i < gpu.rgba.size(); i += 4) set += gpu.rgba[i] > 0.5f;
    EXPECT_EQ(set, size_t(6 * n * n - 12 * n + 8)) << "n " << n;
  }
}

// The box's voxels fill its grid's outer layer, so every ray meeting the grid enters a set
// voxel through the grid's box: the hit distance is the slab-method distance to [−1, 1]³ (double).
TEST_P(Voxelize, DdaHitDistanceIsTheDistanceToTheEnteredFace) {
  const std::vector<Texels> out = render(kVoxelBox, 16);
  const Camera& camera = config_.config.scene.camera;
  double worst = 0;
  int hits = 0, disagree = 0;
  for (uint32_t y = 0; y < kVoxelFrame; ++y)
    for (uint32_t x = 0; x < kVoxelFrame; ++x) {
      const Vec3 d = physics::pixel_ray(camera, kVoxelFrame, kVoxelFrame, x, y);
      const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      double near = -1e30, far = 1e30;
      for (size_t a = 0; a < 3; ++a) {
        const double v = d[a] / length, o = camera.position[a];
        const double t0 = (-1 - o) / v, t1 = (1 - o) / v;
        near = std::max(near, std::min(t0, t1));
        far = std::min(far, std::max(t0, t1));
      }
      const float got = out[2].rgba[4 * (size_t(y) * kVoxelFrame + x)];
      // Rays grazing the box's edges (a chord under 1e-3 m, or missing it by less) may go either way.
      if (std::abs(far - near) < 1e-3) continue;
      const bool meets = near < far;
      if (meets != (got > 0)) {
        ++disagree;
        continue;
      }
      if (!meets) continue;
      ++hits;
      worst = std::max(worst, std::abs(got - near) / near);
    }
  std::printf("%d hits, worst relative |distance − analytic| %.2e, %d disagree\n", hits, worst, disagree);
  EXPECT_GT(hits, 300);
  EXPECT_EQ(disagree, 0);
  EXPECT_LE(worst, 1e-4);
}

TEST_P(Voxelize, NoNaNWithTheCameraInsideTheGrid) {
  for (const std::string camera : {"[0.3, 0.2, 0.1]", "[0, 0, 0]", "[0.999, -0.5, 0.25]"})
    for (const char* object : {kVoxelBox, kVoxelSphere}) {
      const std::vector<Texels> out = render(object, 16, camera);
      EXPECT_TRUE(all_finite(out[1])) << camera;
      EXPECT_TRUE(all_finite(out[2])) << camera;
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, Voxelize, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
