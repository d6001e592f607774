// The atmosphere's lookup-table passes together on both backends (each table's accuracy
// against its double twin is in its pass's file: atmosphere_transmittance_lut_test.cpp,
// atmosphere_multiscattering_lut_test.cpp, atmosphere_skyview_lut_test.cpp,
// atmosphere_aerial_perspective_test.cpp; the fixture is atmosphere_lut.h):
// - cached: a second frame with the same atmosphere runs no LUT pass, a changed atmosphere
//   runs them again, a camera that climbs reruns the sky view alone;
// - no atmosphere in the scene: the pass is culled.
#include <gtest/gtest.h>

#include "tests/gpu/atmosphere_lut.h"

namespace volgraph::testing {
namespace {

class AtmosphereLut : public AtmosphereLutFixture {};

TEST_P(AtmosphereLut, AnUnchangedAtmosphereRunsNoLutPassAChangedOneRunsItAgain) {
  LoadedConfig config = load(R"("atmosphere": { "preset": "earth" })");
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  ASSERT_EQ(executor.timings().size(), 4u);
  for (const PassTiming& t : executor.timings()) EXPECT_FALSE(t.cached) << t.pass << ": the first frame fills the tables";
  executor.run_frame();
  for (const PassTiming& t : executor.timings()) EXPECT_TRUE(t.cached) << t.pass << ": an unchanged atmosphere keeps last frame's table";
  config.config.scene.atmosphere->mie_extinction = {8e-6, 8e-6, 8e-6};
  executor.run_frame();
  for (const PassTiming& t : executor.timings()) EXPECT_FALSE(t.cached) << t.pass << ": a changed atmosphere fills it again";
  config.config.scene.camera.position[1] += 1000;
  executor.run_frame();
  for (const PassTiming& t : executor.timings()) {
    EXPECT_EQ(t.cached, t.pass != "sky" && t.pass != "air") << t.pass << ": a camera 1 km higher changes the sky view and the aerial perspective alone";
  }
  const LutErrors e = transmittance_errors(executor.read_output(0), *config.config.scene.atmosphere);
  EXPECT_LT(e.zenith, 1e-4) << "the table is the changed atmosphere's";
}

TEST_P(AtmosphereLut, NoAtmosphereNoLutPass) {
  const LoadedConfig config = load(R"("background": { "radiance": [0, 0, 0] })");
  const Plan plan = compile_loaded(config);
  EXPECT_TRUE(plan.order.empty());
  EXPECT_EQ(plan.culled.size(), 4u);
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereLut, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
