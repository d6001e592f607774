// The full frame of DESIGN.md at 1920x1080 (tests/fixtures/full_frame): every
// pass runs when the scene has everything; scene needs cull what it lacks; the
// aliased memory stays within 5 % of the lower bound.
#include <gtest/gtest.h>

#include "graph/plan.h"
#include "tests/fixtures/full_frame.h"

namespace volgraph {
namespace {

std::vector<std::string> culled_names(const Graph& g, const Plan& p) {
  std::vector<std::string> out;
  for (const CulledPass& c : p.culled) out.push_back(g.passes[c.pass].name + ":" + std::string(cull_reason_name(c.reason)));
  return out;
}

TEST(FullFrame, EverythingRunsWhenTheSceneHasEverything) {
  const auto frame = fixtures::full_frame();
  const Plan plan = compile(frame.graph);
  EXPECT_EQ(plan.order.size(), frame.graph.passes.size());
  EXPECT_TRUE(plan.culled.empty()) << ::testing::PrintToString(culled_names(frame.graph, plan));
  EXPECT_EQ(frame.graph.passes[plan.order.back().pass].name, "composite");
}

TEST(FullFrame, AliasingIsWithinFivePercentOfTheLowerBound) {
  const auto frame = fixtures::full_frame();
  const Plan plan = compile(frame.graph);
  const MemoryStats& m = plan.memory;
  EXPECT_GE(m.aliased_bytes, m.lower_bound_bytes);
  EXPECT_LE(double(m.aliased_bytes), 1.05 * double(m.lower_bound_bytes))
      << "aliased " << m.aliased_bytes << " lower bound " << m.lower_bound_bytes;
  EXPECT_LT(double(m.aliased_bytes), 0.7 * double(m.unaliased_bytes));
  EXPECT_GT(m.persistent_bytes, 0u);  // froxel and cloud history, atmosphere LUT caches
}

// The memory table of the README (estimated requirements, bench_compile's figures):
// aliasing reaches the lower bound exactly, and --no-alias allocates the unaliased sum.
TEST(FullFrame, AliasedMemoryEqualsTheLowerBound) {
  const auto frame = fixtures::full_frame();
  const MemoryStats aliased = compile(frame.graph).memory;
  EXPECT_EQ(aliased.aliased_bytes, aliased.lower_bound_bytes) << placement_method_name(aliased.method);
  const MemoryStats unaliased = compile(frame.graph, {.alias = false}).memory;
  EXPECT_EQ(unaliased.aliased_bytes, unaliased.unaliased_bytes);
  EXPECT_EQ(unaliased.lower_bound_bytes, aliased.lower_bound_bytes);
}

TEST(FullFrame, ASceneWithoutMediaAtmosphereCloudsOrTranslucencyCullsTheirPasses) {
  const SceneFeatures scene = feature_bit(SceneFeature::geometry) | feature_bit(SceneFeature::lights) |
                              feature_bit(SceneFeature::shadow_casting_light);
  const auto frame = fixtures::full_frame({1920, 1080, 1}, scene);
  const Plan plan = compile(frame.graph);
  EXPECT_EQ(culled_names(frame.graph, plan),
            (std::vector<std::string>{"froxel_voxelize:scene_lacks", "froxel_scatter:scene_lacks",
                                      "scatter_integrate:scene_lacks", "transmittance_lut:scene_lacks",
                                      "multiscatter_lut:scene_lacks", "sky_view_lut:scene_lacks",
                                      "aerial_perspective_lut:scene_lacks", "clouds:scene_lacks",
                                      "translucency:scene_lacks", "translucency_resolve:input_culled",
                                      "refraction_copy:unused", "refraction:scene_lacks"}));
  std::vector<std::string> order;
  for (const PlannedPass& p : plan.order) order.push_back(frame.graph.passes[p.pass].name);
  EXPECT_EQ(order, (std::vector<std::string>{"sun_shadow", "spot_shadow", "depth_prepass", "scene", "composite"}));
}

}  // namespace
}  // namespace volgraph
