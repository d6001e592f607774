// cloud_phase_table (passes/clouds/cloud_phase_table.cpp) and cloud_march's phase_table input
// on both backends: the texture holds physics/mie's texels exactly; an HG lobe through the
// table marches as the analytic HG does (single scattering, back_weight 0: the difference is
// the table's linear interpolation); the Mie table changes the image (the input is read); and
// the march with the table stays finite at the stress extremes. The march against the CPU
// reference with the same table: tests/accuracy/cloud_accuracy_test.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/mie.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing::cloud_phase_table_gpu {

// What a run varies: the table pass (none: the march's dual-lobe HG), the march's
// parameters, the layer, the sun.
struct PhaseRun {
  std::string table_pass;  // a cloud_phase_table pass named "table", or ""
  std::string march_params = "{}";
  std::string clouds = R"("coverage": 0.6)";
  std::string sun = "[0.3, -0.8, -0.5]";
  std::string irradiance = "[3, 3, 3]";
  std::string output = "march.clouds";
};

// A 24 × 24 frame looking up 73° with the sun ahead (forward scattering in view), as
// cloud_march_test.cpp's; the table wired into the march's phase_table when given.
std::string phase_config_text(const PhaseRun& r) {
  const std::string table_input = r.table_pass.empty() ? "" : R"(, "phase_table": "table.phase")";
  return R"({ "output": { "size": [24, 24] },
  "scene": { "camera": { "position": [0, 2, 0], "target": [0, 3, -0.3], "fov_y_deg": 50 },
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "name": "box", "shape": "box", "material": "grey", "size": [1, 1, 1], "transform": { "translate": [0, 0, 6000] } } ],
    "lights": [ { "name": "sun", "type": "directional", "direction": )" + r.sun + R"(, "irradiance": )" + r.irradiance + R"( } ],
    "clouds": { )" + r.clouds + R"( } },
  "graph": { "passes": [
      { "name": "lit", "type": "scene" },
      { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 32, "detail_size": 16, "curl_size": 32 } },
      )" + (r.table_pass.empty() ? "" : r.table_pass + ",") + R"(
      { "name": "march", "type": "cloud_march", "params": )" + r.march_params + R"(,
        "inputs": { "depth": "lit.depth", "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl")" + table_input + R"( } } ],
    "outputs": [")" + r.output + R"("] } })";
}

const char* const kMieTable = R"({ "name": "table", "type": "cloud_phase_table" })";
const char* const kHgTable = R"({ "name": "table", "type": "cloud_phase_table", "variant": "henyey_greenstein", "params": { "g": 0.8 } })";

// Relative RMSE of a's radiance against b's, √(Σ(a − b)²) / √(Σ b²) over rgb, and the worst
// pixel's |a − b| over b's peak.
struct RadianceDifference {
  double rmse = 0, worst = 0;
};
RadianceDifference radiance_difference(const Texels& a, const Texels& b) {
  double squared = 0, b_squared = 0, peak = 0, worst = 0;
  for (size_t i = 0; i < b.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = double(a.rgba[i]) - double(b.rgba[i]);
    squared += d * d, b_squared += double(b.rgba[i]) * b.rgba[i];
    peak = std::max(peak, double(b.rgba[i])), worst = std::max(worst, std::abs(d));
  }
  return {std::sqrt(squared / std::max(b_squared, 1e-30)), worst / std::max(peak, 1e-30)};
}

class CloudPhaseTable : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  Texels render(const PhaseRun& r) {
    const LoadedConfig config = load_config_text("cloud_phase_table.json", phase_config_text(r), registry_);
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    return executor.read_output(0);
  }
  PassRegistry registry_;
};

// The texture holds the texels physics/mie computes, exactly (rgba32float), a = 1.
TEST_P(CloudPhaseTable, TheTextureHoldsThePhysicsTexels) {
  PhaseRun r;
  r.table_pass = kMieTable;
  r.output = "table.phase";
  const Texels t = render(r);
  const physics::CloudPhaseTable expected = physics::cloud_droplet_phase_table({}, 512);
  ASSERT_EQ(t.width, 512u);
  ASSERT_EQ(t.height, 1u);
  for (size_t i = 0; i < expected.texels.size(); ++i) {
    for (size_t c = 0; c < 3; ++c) ASSERT_EQ(t.rgba[4 * i + c], expected.texels[i][c]) << "texel " << i << " channel " << c;
    ASSERT_EQ(t.rgba[4 * i + 3], 1.0f) << "texel " << i;
  }
}

// HG(0.8) through the table against the analytic dual-lobe HG at back_weight 0, one octave
// (more octaves differ by design: the table's octave i is mix(1/4π, p, c^i), HG's is
// HG(c^i g), the same mean cosine, another shape). The difference is the table's linear
// interpolation between texels (≤ 1 % of the phase anywhere at 512 texels, tests/unit/mie_test.cpp;
// far less at this view's 20°–60° from the sun) and fp16 output: measured relative RMSE
// 0.00048, worst pixel 0.00066 of the peak on both backends; bounds 0.002 and 0.003 (a
// half-texel shift of the lookup exceeds them).
TEST_P(CloudPhaseTable, AHenyeyGreensteinTableMarchesAsTheAnalyticLobe) {
  PhaseRun analytic;
  analytic.march_params = R"({ "octaves": 1, "g_forward": 0.8, "back_weight": 0, "jitter": false })";
  PhaseRun tabulated = analytic;
  tabulated.table_pass = kHgTable;
  const Texels a = render(analytic), t = render(tabulated);
  const RadianceDifference d = radiance_difference(t, a);
  std::printf("  HG(0.8) table against the analytic lobe: relative RMSE %.5f, worst %.5f of the peak\n", d.rmse, d.worst);
  EXPECT_LE(d.rmse, 0.002);
  EXPECT_LE(d.worst, 0.003);
  for (size_t i = 3; i < a.rgba.size(); i += 4) ASSERT_EQ(t.rgba[i], a.rgba[i]) << "the phase changes no transmittance";
}

// The Mie table is read: its image differs from the dual-lobe HG's at the defaults (relative
// RMSE above 0.05), and its channels differ (the droplets scatter per wavelength).
TEST_P(CloudPhaseTable, TheMieTableChangesTheImage) {
  PhaseRun hg;
  hg.march_params = R"({ "jitter": false })";
  PhaseRun mie = hg;
  mie.table_pass = kMieTable;
  const Texels h = render(hg), m = render(mie);
  const RadianceDifference d = radiance_difference(m, h);
  std::printf("  Mie table against the dual-lobe HG: relative RMSE %.4f\n", d.rmse);
  EXPECT_GT(d.rmse, 0.05);
  double red = 0, blue = 0;
  for (size_t i = 0; i < m.rgba.size(); i += 4) red += m.rgba[i], blue += m.rgba[i + 2];
  EXPECT_NE(red, blue);
}

// The march with the table at the stress extremes (extinction 100 × the default, a sun of
// 1e5, the sun high, at the horizon and below, every octave and no scaling): finite, T in [0, 1].
TEST_P(CloudPhaseTable, TheMarchWithTheTableStaysFiniteAtTheExtremes) {
  for (const char* sun : {"[0.3, -0.8, -0.5]", "[0, 0, -1]", "[0, 0.4, -0.9]"})
    for (const char* params : {R"({ "octaves": 1, "steps": 1, "light_steps": 1 })", R"({ "octaves": 8, "a": 1, "b": 1, "c": 1, "powder": true })"}) {
      PhaseRun r;
      r.table_pass = kMieTable;
      r.sun = sun;
      r.march_params = params;
      r.irradiance = "[1e5, 1e5, 1e5]";
      r.clouds = R"("coverage": 1, "type": 1, "extinction": 8)";  // 100 × the default 0.08
      const Texels t = render(r);
      for (size_t i = 0; i < t.rgba.size(); i += 4) {
        for (size_t c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(t.rgba[i + c]) && t.rgba[i + c] >= 0) << sun << " " << params;
        ASSERT_GE(t.rgba[i + 3], 0.0f) << sun << " " << params;
        ASSERT_LE(t.rgba[i + 3], 1.0f) << sun << " " << params;
      }
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, CloudPhaseTable, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace volgraph::testing::cloud_phase_table_gpu
