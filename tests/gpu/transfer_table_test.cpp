// transfer_table (passes/volume/transfer_table.cpp) feeding volume_visualize's raymarch on both
// backends: a uniform volume of density d_i = i/4 (gradient exactly 0) through a 5 × 3 table
// whose bottom row is opaque renders the table's texel (d_i, 0) — the first step's opacity is
// 1, so the pixel is that texel's colour — within one step of the output's half float (2⁻¹⁰
// relative: the GPU's conversion may round either way, as the phantom's test allows; measured
// 6.9e-4 at worst on both backends) of the texel's unorm value, though its neighbours differ
// by 50/255 or more (a bilinear fraction of 0.5 % would show): the lookup reads the sample's
// texel alone (volume_transfer_table_position + _mix, the CPU twin's text).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/volume_transfer.h"
#include "tests/gpu/backends.h"
#include "tests/support/nrrd_writer.h"
#include "tools/image_io.h"

namespace volgraph::testing {
namespace {

constexpr int kTableWidth = 5, kTableHeight = 3;

// Texel (i, j) of the table, row j from the bottom (gradient j/2·gradient_max): rgb distinct
// per texel, opaque on the bottom row.
std::array<uint8_t, 4> table_texel(int i, int j) {
  return {uint8_t(40 + 50 * i), uint8_t(200 - 45 * i + 10 * j), uint8_t(i % 2 ? 230 : 20), uint8_t(j == 0 ? 255 : 60)};
}

std::string table_config(const std::string& volume, const std::string& table) {
  return R"({ "output": { "size": [64, 64] },
  "scene": { "camera": { "position": [0, 0.6, 4], "target": [0, 0, 0], "fov_y_deg": 45, "far": 50 },
             "background": { "radiance": [0, 0, 0] },
             "volume_data": { "file": ")" + volume + R"(", "window": [0, 4], "transfer_2d": ")" + table + R"(" } },
  "graph": { "passes": [
      { "name": "lit", "type": "scene" },
      { "name": "volume", "type": "volume_file", "params": { "width": 4, "height": 4, "depth": 4 } },
      { "name": "table", "type": "transfer_table", "params": { "width": 5, "height": 3 } },
      { "name": "draw", "type": "volume_visualize", "variant": "raymarch",
        "params": { "center": [0, 0, 0], "extent": 2, "steps": 16, "gradient_max": 4 },
        "inputs": { "density": "volume.density", "transfer_table": "table.table", "depth": "lit.depth", "scene_color": "lit.color" } } ],
    "outputs": ["draw.color"] } })";
}

class TransferTable : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  PassRegistry registry_;
  test::TempFolder folder_{"transfer_table_gpu"};
};

TEST_P(TransferTable, AUniformVolumeRendersTheTablesSampleExactly) {
  std::vector<uint8_t> image;  // row 0 the image's top: the table's top row
  for (int row = 0; row < kTableHeight; ++row)
    for (int i = 0; i < kTableWidth; ++i)
      for (const uint8_t c : table_texel(i, kTableHeight - 1 - row)) image.push_back(c);
  const std::vector<std::byte> png = encode_png_rgba8(kTableWidth, kTableHeight, image);
  const std::string table = folder_.file("table.png");
  test::write_bytes(table, "", std::vector<char>(reinterpret_cast<const char*>(png.data()), reinterpret_cast<const char*>(png.data()) + png.size()));
  for (int i = 0; i < kTableWidth; ++i) {
    const std::string volume = folder_.file("uniform" + std::to_string(i) + ".nrrd");
    test::write_nrrd(volume, "type: uchar\ndimension: 3\nsizes: 4 4 4\nencoding: raw\n", std::vector<char>(64, char(i)));
    const LoadedConfig config = load_config_text("transfer_table.json", table_config(volume, table), registry_);
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    const Texels color = executor.read_output(0);
    const std::array<uint8_t, 4> want = table_texel(i, 0);
    double worst = 0;
    for (uint32_t y = 24; y < 40; ++y)  // the frame's middle: rays through the box
      for (uint32_t x = 24; x < 40; ++x)
        for (int c = 0; c < 3; ++c) {
          const double exact = want[size_t(c)] / 255.0;
          worst = std::max(worst, std::abs(color.rgba[4 * (size_t(y) * 64 + x) + size_t(c)] - exact) / exact);
        }
    std::printf("density %d/4: worst |pixel − texel (%d, 0)| / texel %.2e (a half-float step: 9.8e-4)\n", i, i, worst);
    EXPECT_LE(worst, std::ldexp(1.0, -10)) << "density " << i << "/4";
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, TransferTable, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
