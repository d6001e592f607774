// Graph compiler benchmark: building and compiling random graphs of 10 … 10,000
// passes (order, culling, lifetimes, aliasing, barriers), and the full frame of
// DESIGN.md's memory figures. Run: build/bench/bench_compile
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "graph/plan.h"
#include "graph/plan_report.h"
#include "tests/fixtures/full_frame.h"
#include "tests/support/graph_recipe.h"

namespace volgraph {
namespace {

// A recorded graph (tests/support/graph_recipe.h): rebuilding it replays the
// GraphBuilder calls that made it. This is the "building" half of the measurement; the
// random generation that chose the graph is not timed.
using test::BenchShape;
using test::GraphRecipe;

const GraphRecipe& recipe(uint32_t passes, BenchShape shape) {
  static std::map<std::pair<uint32_t, BenchShape>, GraphRecipe> cache;  // generated once per size and shape
  auto it = cache.find({passes, shape});
  if (it == cache.end()) {
    it = cache.emplace(std::pair{passes, shape}, test::record_recipe(test::make_random_graph(test::bench_graph_options(passes, shape))))
             .first;
  }
  return it->second;
}

void report_memory(benchmark::State& state, const Plan& plan) {
  const MemoryStats& m = plan.memory;
  state.counters["aliasing_saving_%"] = 100.0 * (1.0 - double(m.aliased_bytes) / double(std::max<uint64_t>(1, m.unaliased_bytes)));
  state.counters["aliased/lower_bound"] = double(m.aliased_bytes) / double(std::max<uint64_t>(1, m.lower_bound_bytes));
  state.counters["barriers"] = double(plan.barriers.size());
}

void build_and_compile(benchmark::State& state, BenchShape shape) {
  const GraphRecipe& r = recipe(uint32_t(state.range(0)), shape);
  Plan plan;
  for (auto _ : state) {
    Graph g = test::rebuild(r);
    plan = compile(g);
    benchmark::DoNotOptimize(plan.order.data());
  }
  report_memory(state, plan);
  state.counters["live_passes"] = double(plan.order.size());
  state.counters["ns_per_pass"] = benchmark::Counter(double(state.range(0)) * double(state.iterations()),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(std::string(placement_method_name(plan.memory.method)));
}

void BM_BuildAndCompile_FrameLike(benchmark::State& state) { build_and_compile(state, BenchShape::frame_like); }
void BM_BuildAndCompile_Stress(benchmark::State& state) { build_and_compile(state, BenchShape::stress); }
BENCHMARK(BM_BuildAndCompile_FrameLike)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BuildAndCompile_Stress)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_CompileOnly_FrameLike(benchmark::State& state) {
  const GraphRecipe& r = recipe(uint32_t(state.range(0)), BenchShape::frame_like);
  for (auto _ : state) {
    Plan plan = compile(r.source.graph);
    benchmark::DoNotOptimize(plan.order.data());
  }
}
BENCHMARK(BM_CompileOnly_FrameLike)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_FullFrame(benchmark::State& state) {
  const auto frame = fixtures::full_frame();
  Plan plan;
  for (auto _ : state) {
    plan = compile(frame.graph);
    benchmark::DoNotOptimize(plan.order.data());
  }
  report_memory(state, plan);
}
BENCHMARK(BM_FullFrame)->Unit(benchmark::kMicrosecond);

void print_full_frame_memory() {
  const auto frame = fixtures::full_frame();
  std::printf("Full frame of DESIGN.md at 1920x1080 (%zu passes, %zu resources; tests/fixtures/full_frame.cpp):\n",
              frame.graph.passes.size(), frame.graph.resources.size());
  std::printf("  %-10s %10s %10s %12s %11s\n", "", "unaliased", "aliased", "lower bound", "persistent");
  for (const bool alias : {true, false}) {
    const Plan plan = compile(frame.graph, {.alias = alias});
    const MemoryStats& m = plan.memory;
    std::printf("  %-10s %10s %10s %12s %11s   aliased/lower bound %.3f, saving %.1f %%\n",
                alias ? "aliasing" : "--no-alias", bytes_text(m.unaliased_bytes).c_str(), bytes_text(m.aliased_bytes).c_str(),
                bytes_text(m.lower_bound_bytes).c_str(), bytes_text(m.persistent_bytes).c_str(),
                double(m.aliased_bytes) / double(m.lower_bound_bytes),
                100.0 * (1.0 - double(m.aliased_bytes) / double(m.unaliased_bytes)));
  }
  std::printf("\n");
}

}  // namespace
}  // namespace volgraph

int main(int argc, char** argv) {
  volgraph::print_full_frame_memory();
  // Medians over repeated runs; the caller's own flags come later and win.
  char repetitions[] = "--benchmark_repetitions=7";
  char aggregates[] = "--benchmark_report_aggregates_only=true";
  std::vector<char*> args = {argv[0], repetitions, aggregates};
  args.insert(args.end(), argv + 1, argv + argc);
  int n = int(args.size());
  benchmark::Initialize(&n, args.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
