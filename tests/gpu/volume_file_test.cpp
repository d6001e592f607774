// volume_file (passes/volume/volume_file.cpp) on both backends, with NRRD files the tests
// write: the texture holds the file's samples mapped through the window, each the half float
// the CPU makes of it bit for bit (rgba16float; so within one half-float step, 2⁻¹¹ relative, of
// the exact value); the volume is cached until the file changes; volume_visualize's
// `box: volume_data` gives the box the proportions of sizes × spacing, so a NRRD sphere
// sampled at 64 × 64 × 32 with z spacing 2 has the phantom's isosurface radius, and the same
// samples at spacing 1 draw a sphere flattened to half its height.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/volume_phantom.h"
#include "tests/gpu/backends.h"
#include "tests/support/nrrd_writer.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kFrame = 64;

// A graph of volume_file alone, or of volume_file feeding volume_visualize's isosurface over
// an empty black scene (a 2 m box at the origin shaped by the file), reading `file`.
std::string file_config(const std::string& file, const std::string& volume_data_extra, std::array<int, 3> sizes, bool visualize,
                        const std::string& iso = "0.5") {
  const std::string read = R"({ "name": "volume", "type": "volume_file", "params": { "width": )" + std::to_string(sizes[0]) +
                           R"(, "height": )" + std::to_string(sizes[1]) + R"(, "depth": )" + std::to_string(sizes[2]) + " } }";
  const std::string draw = R"(, { "name": "lit", "type": "scene" },
      { "name": "draw", "type": "volume_visualize", "variant": "isosurface",
        "params": { "center": [0, 0, 0], "extent": 2, "box": "volume_data", "iso": )" + iso + R"(, "steps": 64 },
        "inputs": { "density": "volume.density", "depth": "lit.depth", "scene_color": "lit.color" } })";
  return R"({ "output": { "size": [64, 64] },
  "scene": { "camera": { "position": [0, 0.6, 4], "target": [0, 0, 0], "fov_y_deg": 45, "far": 50 },
             "background": { "radiance": [0, 0, 0] },
             "volume_data": { "file": ")" + file + "\"" + volume_data_extra + R"( } },
  "graph": { "passes": [ )" + read + (visualize ? draw : "") + R"( ],
    "outputs": [)" + (visualize ? R"("draw.hit", "draw.surface_normal")" : R"("volume.density")") + "] } }";
}

// The sphere phantom's ramp (physics/volume_phantom.h, radius 0.35, shell 0.1 of the box)
// at the texel centres of a `sizes` grid, as uchar samples.
std::vector<uint8_t> sphere_samples(std::array<int, 3> sizes) {
  std::vector<uint8_t> out;
  for (int k = 0; k < sizes[2]; ++k)
    for (int j = 0; j < sizes[1]; ++j)
      for (int i = 0; i < sizes[0]; ++i) {
        const glm::vec3 p = (glm::vec3(i, j, k) + 0.5f) / glm::vec3(sizes[0], sizes[1], sizes[2]);
        out.push_back(uint8_t(std::lround(physics::volume_phantom::volume_sphere_density(p, 0.35f, 0.1f) * 255.0f)));
      }
  return out;
}

class VolumeFile : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const std::string& text) { return load_config_text("volume_file.json", text, registry_); }
  PassRegistry registry_;
  test::TempFolder folder_{"volume_file_gpu"};
};

// ushort big-endian samples through the window [1000, 3000]: every texel the CPU's half float
// of (v − 1000) / 2000 clamped, bit for bit; x fastest, then y, then z.
TEST_P(VolumeFile, TheTextureHoldsTheFilesSamplesThroughTheWindow) {
  const std::array<int, 3> sizes{5, 4, 3};
  std::vector<uint16_t> samples;
  for (int i = 0; i < 60; ++i) samples.push_back(uint16_t(500 + i * 47));
  const std::string path = folder_.file("window.nrrd");
  test::write_nrrd(path, "type: ushort\ndimension: 3\nsizes: 5 4 3\nendian: big\nencoding: raw\nspacings: 1 1 1\n", test::sample_bytes(samples, true));
  const LoadedConfig config = load(file_config(path, R"(, "window": [1000, 3000])", sizes, false));
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  const Texels t = executor.read_output(0);
  ASSERT_EQ(t.width * t.height * t.depth, 60u);
  ASSERT_EQ(t.depth, 3u);
  double worst_relative = 0;
  for (size_t i = 0; i < 60; ++i) {
    const float exact = std::clamp((float(samples[i]) - 1000.0f) / 2000.0f, 0.0f, 1.0f);
    const float half = glm::unpackHalf1x16(glm::packHalf1x16(exact));
    EXPECT_EQ(t.rgba[4 * i], half) << "texel " << i << " (sample " << samples[i] << ")";
    if (exact > 0) worst_relative = std::max(worst_relative, std::abs(double(t.rgba[4 * i]) - exact) / exact);
  }
  std::printf("worst |texel − exact| / exact %.2e (a half float's step: 2^-11 = 4.9e-4 relative)\n", worst_relative);
  EXPECT_LE(worst_relative, std::ldexp(1.0, -11));
}

// The volume is read once; a second frame is cached; the file rewritten (a later time of
// change) is read again with its new samples.
TEST_P(VolumeFile, TheVolumeIsReadAgainOnlyWhenTheFileChanges) {
  const std::string path = folder_.file("cached.nrrd");
  const std::string header = "type: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n";
  test::write_nrrd(path, header, std::vector<char>(8, char(51)));
  const LoadedConfig config = load(file_config(path, "", {2, 2, 2}, false));
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  EXPECT_FALSE(executor.timings()[0].cached);
  executor.run_frame();
  EXPECT_TRUE(executor.timings()[0].cached) << "the same file";
  const auto before = std::filesystem::last_write_time(path);
  test::write_nrrd(path, header, std::vector<char>(8, char(102)));
  std::filesystem::last_write_time(path, before + std::chrono::seconds(1));
  executor.run_frame();
  EXPECT_FALSE(executor.timings()[0].cached) << "the file rewritten";
  EXPECT_EQ(executor.read_output(0).rgba[0], glm::unpackHalf1x16(glm::packHalf1x16(0.4f)));
}

// A 64 × 64 × 32 uchar sphere phantom (radius 0.35, shell 0.1 of the unit box) at z spacing 2
// spans a cube: the isosurface at 0.5 and 0.3 is the phantom's sphere of radius
// (0.35 + (0.5 − ρ)·0.1) × 2 m within 0.1 texel of x (the phantom test's 0.05 texel, doubled for
// z's texels twice as long and the samples' uchar steps, ±0.2 mm). At z spacing 1 the same
// samples span a box half as deep: the surface is that sphere with z halved.
TEST_P(VolumeFile, TheBoxFollowsSizesTimesSpacing) {
  const std::array<int, 3> sizes{64, 64, 32};
  const std::vector<uint8_t> samples = sphere_samples(sizes);
  const double texel = 2.0 / 64;
  for (const double z_spacing : {2.0, 1.0}) {
    const std::string path = folder_.file("sphere.nrrd");
    test::write_nrrd(path, "type: uchar\ndimension: 3\nsizes: 64 64 32\nencoding: raw\nspace directions: (1,0,0) (0,1,0) (0,0," +
                               std::to_string(z_spacing) + ")\n", test::sample_bytes(samples));
    for (const double iso : {0.5, 0.3}) {
      const LoadedConfig config = load(file_config(path, "", sizes, true, std::to_string(iso)));
      Executor executor(device(), config.graph, &config.config.scene, {});
      executor.run_frame();
      const Texels hit = executor.read_output(0);
      const double radius = physics::volume_phantom::volume_sphere_iso_radius(float(iso), 0.35f, 0.1f) * 2.0;
      const double stretch = 2.0 / z_spacing;  // the box's depth is z_spacing / 2 of its width
      double worst = 0;
      int hits = 0;
      for (size_t p = 0; p < size_t(kFrame) * kFrame; ++p) {
        if (hit.rgba[4 * p + 3] != 1.0f) continue;
        ++hits;
        const glm::dvec3 at(hit.rgba[4 * p], hit.rgba[4 * p + 1], hit.rgba[4 * p + 2] * stretch);
        worst = std::max(worst, std::abs(glm::length(at) - radius));
      }
      std::printf("z spacing %.0f, iso %.1f: %d hits, worst |r − R| %.5f m (%.3f texels)\n", z_spacing, iso, hits, worst, worst / texel);
      EXPECT_GT(hits, 300) << "z spacing " << z_spacing << ", iso " << iso;
      EXPECT_LE(worst, 0.1 * texel) << "z spacing " << z_spacing << ", iso " << iso;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, VolumeFile, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
