// Transient memory on Vulkan: the compiler places resources by the driver's real
// requirements, the backend allocates exactly the plan's heaps and binds every
// resource at its planned offset, and the validation layer stays silent.
#include <gtest/gtest.h>

#include "tests/gpu/validation_messages.h"

#include "graph/config/config.h"
#include "graph/rhi/vulkan/graph_resources.h"
#include "passes/passes.h"
#include "tests/fixtures/full_frame.h"
#include "tests/support/source_dir.h"

namespace volgraph::vulkan {
namespace {

class GraphResourcesTest : public ::testing::TestWithParam<const char*> {
 protected:
  static void SetUpTestSuite() { context_ = Context::create({.validation = true}).release(); }
  static void TearDownTestSuite() { delete context_; }
  void TearDown() override {
    const auto messages = context_->take_validation_messages();
    EXPECT_TRUE(messages.empty()) << joined(messages);
  }

  // Compiles `graph` with the backend's requirements, binds, and checks the bytes.
  static void expect_plan_matches_allocation(const Graph& graph, const CompileOptions& options) {
    GraphResources resources(*context_, graph);
    const Plan plan = compile(graph, options, resources.requirements());
    resources.bind(plan);
    EXPECT_EQ(resources.transient_bytes(), plan.memory.aliased_bytes);
    EXPECT_EQ(resources.persistent_bytes(), plan.memory.persistent_bytes);
    if (!options.alias) EXPECT_EQ(resources.transient_bytes(), plan.memory.unaliased_bytes);
  }

  static Context* context_;
};

Context* GraphResourcesTest::context_ = nullptr;

TEST_P(GraphResourcesTest, PlanMemoryIsWhatVulkanAllocates) {
  PassRegistry registry;
  register_builtin_passes(registry);
  const LoadedConfig loaded = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/" + GetParam(), registry);
  expect_plan_matches_allocation(loaded.graph, {});
  expect_plan_matches_allocation(loaded.graph, {.alias = false});
}

INSTANTIATE_TEST_SUITE_P(Configs, GraphResourcesTest,
                         ::testing::Values("demo_primitives.json", "demo_point_lights.json", "refraction_copy.json"));

TEST_F(GraphResourcesTest, FullFrameAliasesRealImagesWithinFivePercentOfTheLowerBound) {
  const auto frame = fixtures::full_frame();
  GraphResources resources(*context_, frame.graph);
  const Plan plan = compile(frame.graph, {}, resources.requirements());
  resources.bind(plan);
  EXPECT_EQ(resources.transient_bytes(), plan.memory.aliased_bytes);
  EXPECT_LE(double(plan.memory.aliased_bytes), 1.05 * double(plan.memory.lower_bound_bytes));
  EXPECT_FALSE(plan.handovers.empty());
}

}  // namespace
}  // namespace volgraph::vulkan
