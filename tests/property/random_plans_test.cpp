// Thousands of random graphs, each compiled with every option combination and checked
// by the independent plan checker. Seeds are fixed, so a failure names the seed that
// reproduces it (VOLGRAPH_PROPERTY_SEED=N runs one seed with a full dump).
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>

#include "tests/property/property_common.h"

namespace volgraph::test {
namespace {

constexpr int kShards = 4;

// Graphs per option combination; VOLGRAPH_PROPERTY_GRAPHS overrides.
uint64_t graphs_per_combo() { return env_u64("VOLGRAPH_PROPERTY_GRAPHS", 4000); }

// Compiles and checks one seed; returns false (after reporting) on a violation.
bool check_seed(uint64_t seed, const Combo& combo, bool verbose) {
  const RandomGraphOptions o = options_for_seed(seed);
  const RandomGraph g = make_random_graph(o);
  const RequirementsFn req = requirements_for_seed(seed);
  Plan plan;
  try {
    plan = compile(g.graph, combo.options, req);
  } catch (const std::exception& e) {
    ADD_FAILURE() << describe(seed, o, combo.name) << "\ncompile() threw: " << e.what();
    return false;
  }
  std::vector<std::string> v = check_plan(g.graph, plan, combo.options, req);
  for (std::string& violation : check_pool(g.graph, plan, pool_resources(g.graph, plan))) v.push_back(std::move(violation));
  if (verbose) std::cout << graph_text(g.graph) << plan_text(g.graph, plan);
  if (!v.empty()) {
    ADD_FAILURE() << describe(seed, o, combo.name) << "\n"
                  << v.size() << " violation(s):\n"
                  << first_violations(v);
    return false;
  }
  return true;
}

class RandomPlans : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(RandomPlans, CheckerFindsNoViolation) {
  const Combo& combo = combos()[std::get<0>(GetParam())];
  const int shard = std::get<1>(GetParam());
  const uint64_t total = graphs_per_combo();
  int failures = 0;
  for (uint64_t seed = 1 + shard; seed <= total; seed += kShards) {
    if (!check_seed(seed, combo, false) && ++failures >= 5) {
      ADD_FAILURE() << "stopping this shard after 5 failing seeds";
      return;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllOptions, RandomPlans,
                         ::testing::Combine(::testing::Range(0, 4), ::testing::Range(0, kShards)),
                         [](const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
                           return std::string(combos()[std::get<0>(info.param)].name) + "_shard" +
                                  std::to_string(std::get<1>(info.param));
                         });

// Reproduce one seed (all combinations) with a dump of the graph and plan.
TEST(RandomPlansRepro, OneSeed) {
  const uint64_t seed = env_u64("VOLGRAPH_PROPERTY_SEED", 0);
  if (seed == 0) GTEST_SKIP() << "set VOLGRAPH_PROPERTY_SEED=N to run one seed";
  const uint64_t only = env_u64("VOLGRAPH_PROPERTY_COMBO", 99);
  for (size_t c = 0; c < combos().size(); ++c) {
    if (only != 99 && only != c) continue;
    std::cout << "=== " << combos()[c].name << "\n";
    check_seed(seed, combos()[c], true);
  }
}

// A few large graphs: the checker still holds at scale, and compile stays fast.
TEST(RandomPlansLarge, ThousandsOfPasses) {
  for (uint64_t seed : {9001ull, 9002ull, 9003ull}) {
    RandomGraphOptions o;
    o.seed = seed;
    o.passes = 2000;
    o.locality = seed == 9003 ? 64 : 8;
    o.output_fraction = 0.05;
    const RandomGraph g = make_random_graph(o);
    for (const Combo& combo : combos()) {
      Plan plan;
      ASSERT_NO_THROW(plan = compile(g.graph, combo.options)) << "seed " << seed << " " << combo.name;
      const auto v = check_plan(g.graph, plan, combo.options);
      EXPECT_TRUE(v.empty()) << "seed=" << seed << " passes=2000 options=" << combo.name << "\n"
                             << first_violations(v);
    }
  }
}

TEST(RandomPlansLarge, TenThousandPassesCompile) {
  RandomGraphOptions o;
  o.seed = 10000;
  o.passes = 10000;
  o.allow_needs = false;  // keep most of the graph alive
  o.output_fraction = 0.2;
  const auto t0 = std::chrono::steady_clock::now();
  const RandomGraph g = make_random_graph(o);
  const auto t1 = std::chrono::steady_clock::now();
  Plan plan;
  ASSERT_NO_THROW(plan = compile(g.graph));
  const auto t2 = std::chrono::steady_clock::now();
  const auto v = check_plan(g.graph, plan, CompileOptions{});
  const auto t3 = std::chrono::steady_clock::now();
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  std::cout << "10k passes: generate " << ms(t0, t1) << " ms, compile " << ms(t1, t2) << " ms, check "
            << ms(t2, t3) << " ms; " << g.graph.resources.size() << " resources, " << plan.order.size()
            << " passes run, " << plan.barriers.size() << " barriers\n";
  EXPECT_TRUE(v.empty()) << first_violations(v);
}

// The generator itself: reproducible, and graphs of the requested size.
TEST(RandomGraphGenerator, SameSeedSameGraph) {
  for (uint64_t seed = 1; seed <= 50; ++seed) {
    const RandomGraphOptions o = options_for_seed(seed);
    const RandomGraph a = make_random_graph(o);
    const RandomGraph b = make_random_graph(o);
    ASSERT_EQ(graph_text(a.graph), graph_text(b.graph)) << "seed " << seed;
    EXPECT_EQ(a.graph.passes.size(), o.passes);
    EXPECT_FALSE(a.graph.outputs.empty());
  }
}

TEST(RandomGraphGenerator, DeclarationOrderIsNotDependencyOrder) {
  // Over many seeds, some pass reads a resource made by a pass declared after it.
  int backwards = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    RandomGraphOptions o;
    o.seed = seed;
    o.passes = 50;
    const RandomGraph g = make_random_graph(o);
    for (uint32_t p = 0; p < g.graph.passes.size(); ++p) {
      for (const ResourceUse& u : g.graph.passes[p].uses) {
        if (u.direction == SlotDirection::output) continue;
        if (g.graph.resources[u.resource].version_writers[u.version] > p) ++backwards;
      }
    }
  }
  EXPECT_GT(backwards, 100);
}

TEST(RandomGraphGenerator, CoversTheFeaturesTheCheckerTests) {
  // Across the seeds of the suite, every kind of use, inouts, optional inputs left
  // unbound or bound, persistent outputs, history pairs, needs that fail, and culling all appear.
  std::vector<int> usage_seen(11, 0);
  int inout = 0, optional_bound = 0, persistent = 0, history_pairs = 0, failing_needs = 0, multi_use = 0;
  int culled_scene = 0, culled_input = 0, culled_unused = 0, forwarded = 0;
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    const RandomGraph g = make_random_graph(options_for_seed(seed));
    for (const GraphPass& p : g.graph.passes) {
      if (!needs_hold(p.needs, p.needs_any, g.graph.scene)) ++failing_needs;
      for (size_t i = 0; i < p.uses.size(); ++i) {
        const ResourceUse& u = p.uses[i];
        ++usage_seen[static_cast<size_t>(u.usage)];
        if (u.direction == SlotDirection::inout) ++inout;
        if (u.optional) ++optional_bound;
        for (size_t j = 0; j < i; ++j) multi_use += p.uses[j].resource == u.resource;
      }
    }
    for (const GraphResource& r : g.graph.resources) {
      persistent += r.desc.persistent;
      history_pairs += r.previous != kNone;
    }
    const ExpectedCulling c = expected_culling(g.graph, true);
    for (const auto& reason : c.reason) {
      if (!reason) continue;
      culled_scene += *reason == CullReason::scene_lacks;
      culled_input += *reason == CullReason::input_culled;
      culled_unused += *reason == CullReason::unused;
    }
    // A modifier culled for its needs whose next version a live pass reads (forwarding).
    for (uint32_t p = 0; p < g.graph.passes.size(); ++p) {
      if (c.reason[p] != CullReason::scene_lacks) continue;
      for (const ResourceUse& u : g.graph.passes[p].uses) {
        if (u.direction != SlotDirection::inout) continue;
        for (uint32_t q = 0; q < g.graph.passes.size(); ++q) {
          if (!c.live[q]) continue;
          for (const ResourceUse& x : g.graph.passes[q].uses) {
            forwarded += x.direction != SlotDirection::output && x.resource == u.resource && x.version == u.version + 1;
          }
        }
      }
    }
  }
  for (size_t u = 0; u < usage_seen.size(); ++u) {
    EXPECT_GT(usage_seen[u], 0) << "usage " << usage_name(static_cast<Usage>(u)) << " never generated";
  }
  EXPECT_GT(inout, 0);
  EXPECT_GT(optional_bound, 0);
  EXPECT_GT(persistent, 0);
  EXPECT_GT(history_pairs, 0);
  EXPECT_GT(failing_needs, 0);
  EXPECT_GT(multi_use, 0);
  EXPECT_GT(culled_scene, 0);
  EXPECT_GT(culled_input, 0);
  EXPECT_GT(culled_unused, 0);
  EXPECT_GT(forwarded, 0);
}

}  // namespace
}  // namespace volgraph::test
