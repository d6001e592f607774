// Determinism, and that each option changes only its own aspect of the plan.
#include <gtest/gtest.h>

#include "tests/property/property_common.h"

namespace volgraph::test {
namespace {

constexpr uint64_t kSeeds = 300;

TEST(Determinism, SameGraphSamePlan) {
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const RandomGraphOptions o = options_for_seed(seed);
    const RandomGraph g = make_random_graph(o);
    const Graph copy = g.graph;  // a separate copy must not change anything either
    const RequirementsFn req = requirements_for_seed(seed);
    for (const Combo& combo : combos()) {
      const Plan a = compile(g.graph, combo.options, req);
      const Plan b = compile(g.graph, combo.options, req);
      const Plan c = compile(copy, combo.options, req);
      const std::string ab = plan_difference(a, b, kAll);
      const std::string ac = plan_difference(a, c, kAll);
      EXPECT_EQ(ab, "") << describe(seed, o, combo.name) << "\ncompiling twice gives different plans";
      EXPECT_EQ(ac, "") << describe(seed, o, combo.name) << "\ncompiling a copy of the graph gives another plan";
      if (!ab.empty() || !ac.empty()) return;
    }
  }
}

TEST(OptionAspects, NoCullKeepsEveryPass) {
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const RandomGraphOptions o = options_for_seed(seed);
    const RandomGraph g = make_random_graph(o);
    const Plan p = compile(g.graph, combos()[1].options);
    ASSERT_TRUE(p.culled.empty()) << describe(seed, o, "no_cull");
    ASSERT_EQ(p.order.size(), g.graph.passes.size()) << describe(seed, o, "no_cull");
  }
}

TEST(OptionAspects, NoAliasKeepsOrderCullingAndLifetimes) {
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const RandomGraphOptions o = options_for_seed(seed);
    const RandomGraph g = make_random_graph(o);
    const RequirementsFn req = requirements_for_seed(seed);
    const Plan base = compile(g.graph, CompileOptions{}, req);
    const Plan no_alias = compile(g.graph, combos()[2].options, req);
    const std::string d = plan_difference(base, no_alias, kOrder | kCulled | kLifetimes);
    ASSERT_EQ(d, "") << describe(seed, o, "no_alias vs default");
    EXPECT_TRUE(no_alias.handovers.empty()) << describe(seed, o, "no_alias");
    EXPECT_EQ(no_alias.memory.unaliased_bytes, base.memory.unaliased_bytes) << describe(seed, o, "no_alias");
    EXPECT_EQ(no_alias.memory.lower_bound_bytes, base.memory.lower_bound_bytes) << describe(seed, o, "no_alias");
    for (const Barrier& b : no_alias.barriers) {
      ASSERT_FALSE(b.aliasing) << describe(seed, o, "no_alias") << "\nan aliasing barrier without aliasing";
    }
  }
}

TEST(OptionAspects, SerializeKeepsOrderCullingAndPlacements) {
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const RandomGraphOptions o = options_for_seed(seed);
    const RandomGraph g = make_random_graph(o);
    const RequirementsFn req = requirements_for_seed(seed);
    const Plan base = compile(g.graph, CompileOptions{}, req);
    const Plan ser = compile(g.graph, combos()[3].options, req);
    const std::string d = plan_difference(base, ser, kOrder | kCulled | kLifetimes | kPlacements | kHandovers | kMemory);
    ASSERT_EQ(d, "") << describe(seed, o, "serialize vs default");
  }
}

TEST(OptionAspects, AliasingNeverCostsMore) {
  uint64_t saved = 0;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const RandomGraphOptions o = options_for_seed(seed);
    const RandomGraph g = make_random_graph(o);
    const Plan base = compile(g.graph);
    const Plan no_alias = compile(g.graph, combos()[2].options);
    EXPECT_LE(base.memory.aliased_bytes, no_alias.memory.aliased_bytes) << describe(seed, o, "default");
    saved += no_alias.memory.aliased_bytes - std::min(no_alias.memory.aliased_bytes, base.memory.aliased_bytes);
  }
  EXPECT_GT(saved, 0u) << "aliasing never saved a byte over " << kSeeds << " graphs";
}

}  // namespace
}  // namespace volgraph::test
