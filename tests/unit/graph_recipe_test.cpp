// The benchmark's graphs (bench/bench_compile.cpp) at small sizes: recording a random
// graph as GraphBuilder calls and replaying them gives the same graph, which compiles
// to a plan the independent checker accepts — so that the benchmark cannot break unseen.
#include <gtest/gtest.h>

#include <string>

#include "graph/plan.h"
#include "tests/support/graph_recipe.h"
#include "tests/support/plan_checker.h"

namespace volgraph::test {
namespace {

// Field-by-field differences between two graphs, one line each (empty: equal).
std::string graph_differences(const Graph& a, const Graph& b) {
  std::string out;
  auto note = [&](bool same, const std::string& what) {
    if (!same) out += what + "\n";
  };
  note(a.output_size == b.output_size && a.scene == b.scene, "output size or scene");
  note(a.passes.size() == b.passes.size(), "pass count");
  note(a.resources.size() == b.resources.size(), "resource count");
  note(a.outputs == b.outputs, "graph outputs");
  if (!out.empty()) return out;
  for (size_t p = 0; p < a.passes.size(); ++p) {
    const GraphPass& x = a.passes[p];
    const GraphPass& y = b.passes[p];
    note(x.name == y.name && x.decl == y.decl && x.variant == y.variant && x.kind == y.kind && x.needs == y.needs && x.needs_any == y.needs_any,
         "pass " + std::to_string(p) + " header");
    bool same_uses = x.uses.size() == y.uses.size();
    for (size_t k = 0; same_uses && k < x.uses.size(); ++k) {
      const ResourceUse& u = x.uses[k];
      const ResourceUse& v = y.uses[k];
      same_uses = u.resource == v.resource && u.version == v.version && u.slot == v.slot && u.usage == v.usage &&
                  u.direction == v.direction && u.optional == v.optional;
    }
    note(same_uses, "pass " + std::to_string(p) + " '" + x.name + "' uses");
  }
  for (size_t r = 0; r < a.resources.size(); ++r) {
    const GraphResource& x = a.resources[r];
    const GraphResource& y = b.resources[r];
    note(x.desc.name == y.desc.name && x.desc.kind == y.desc.kind && x.desc.format == y.desc.format &&
             x.desc.extent == y.desc.extent && x.desc.buffer_bytes == y.desc.buffer_bytes &&
             x.desc.persistent == y.desc.persistent,
         "resource " + std::to_string(r) + " desc");
    note(x.creator == y.creator && x.version_writers == y.version_writers && x.previous == y.previous &&
             x.previous_of == y.previous_of,
         "resource " + std::to_string(r) + " '" + x.desc.name + "' wiring");
  }
  return out;
}

bool has_history(const Graph& g) {
  for (const GraphResource& r : g.resources) {
    if (r.previous_of != kNone) return true;
  }
  return false;
}

// Rebuilds the recipe, compares with its source, compiles, and checks the plan.
void expect_rebuild_compiles(const GraphRecipe& recipe, const std::string& what) {
  Graph rebuilt;
  ASSERT_NO_THROW(rebuilt = rebuild(recipe)) << what;
  EXPECT_EQ(graph_differences(recipe.source.graph, rebuilt), "") << what;
  Plan plan;
  ASSERT_NO_THROW(plan = compile(rebuilt)) << what;
  const std::vector<std::string> violations = check_plan(rebuilt, plan, CompileOptions{});
  EXPECT_TRUE(violations.empty()) << what << ": " << violations.size() << " violations, first: " << violations.front();
}

TEST(BenchGraphs, BothShapesRebuildAndCompile) {
  for (const BenchShape shape : {BenchShape::frame_like, BenchShape::stress}) {
    for (const uint32_t passes : {10u, 100u, 1000u}) {
      const std::string what = std::string(shape == BenchShape::frame_like ? "frame-like" : "stress") + ", " +
                               std::to_string(passes) + " passes";
      const GraphRecipe recipe = record_recipe(make_random_graph(bench_graph_options(passes, shape)));
      expect_rebuild_compiles(recipe, what);
    }
  }
}

// Histories (read_history) are the builder call the benchmark's replay once lacked: seeds
// of the property tests' shape with temporal passes.
TEST(BenchGraphs, GraphsWithHistoriesRebuild) {
  int with_history = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    RandomGraphOptions o;
    o.seed = seed;
    o.passes = 60;
    const GraphRecipe recipe = record_recipe(make_random_graph(o));
    with_history += has_history(recipe.source.graph);
    expect_rebuild_compiles(recipe, "seed " + std::to_string(seed));
  }
  EXPECT_GT(with_history, 10) << "too few of these graphs have a history to cover read_history";
}

// The frame-like shape keeps most passes live, as a frame does (the benchmark's figures
// would otherwise measure mostly culling).
TEST(BenchGraphs, FrameLikeKeepsMostPassesLive) {
  for (const uint32_t passes : {100u, 1000u}) {
    const RandomGraph g = make_random_graph(bench_graph_options(passes, BenchShape::frame_like));
    const Plan plan = compile(g.graph);
    EXPECT_GE(plan.order.size(), passes * 9 / 10) << passes << " passes";
  }
}

}  // namespace
}  // namespace volgraph::test
