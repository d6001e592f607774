// Graph compiler benchmark: building and compiling random graphs of 10 … 10,000
// passes (order, culling, lifetimes, aliasing, barriers), and the full frame of
// DESIGN.md's memory figures. Run: build/bench/bench_compile
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <vector>

#include "graph/plan.h"
#include "graph/plan_report.h"
#include "tests/fixtures/full_frame.h"
#include "tests/support/random_graph.h"

namespace volgraph {
namespace {

// A recorded graph: rebuilding it replays the GraphBuilder calls that made it, in an
// order where every resource exists before it is read. This is the "building" half of
// the measurement; the random generation that chose the graph is not timed.
struct Recipe {
  test::RandomGraph source;
  std::vector<uint32_t> build_order;
};

Recipe record(uint32_t passes) {
  test::RandomGraphOptions o;
  o.passes = passes;
  o.seed = 20261121 + passes;
  Recipe r{test::make_random_graph(o), {}};
  const Plan all = compile(r.source.graph, {.cull = false});
  for (const PlannedPass& p : all.order) r.build_order.push_back(p.pass);
  return r;
}

Graph rebuild(const Recipe& r) {
  const Graph& g = r.source.graph;
  GraphBuilder b(g.output_size, g.scene);
  for (const GraphPass& p : g.passes) b.add_pass(p.name, *p.decl, p.variant);
  std::vector<std::vector<ResourceVersion>> made(g.resources.size());
  for (uint32_t p : r.build_order) {
    for (const ResourceUse& u : g.passes[p].uses) {
      if (u.direction == SlotDirection::output) {
        made[u.resource].push_back(b.create(p, u.slot, g.resources[u.resource].desc));
      } else if (u.direction == SlotDirection::inout) {
        made[u.resource].push_back(b.modify(p, u.slot, made[u.resource][u.version]));
      } else {
        b.read(p, u.slot, made[u.resource][u.version]);
      }
    }
  }
  for (const ResourceVersion& o : g.outputs) b.mark_output(made[o.resource][o.version]);
  return b.finish();
}

const Recipe& recipe(uint32_t passes) {
  static std::map<uint32_t, Recipe> cache;  // benchmark fixtures outlive one run only here
  auto it = cache.find(passes);
  if (it == cache.end()) it = cache.emplace(passes, record(passes)).first;
  return it->second;
}

void report_memory(benchmark::State& state, const Plan& plan) {
  const MemoryStats& m = plan.memory;
  state.counters["aliasing_saving_%"] = 100.0 * (1.0 - double(m.aliased_bytes) / double(std::max<uint64_t>(1, m.unaliased_bytes)));
  state.counters["aliased/lower_bound"] = double(m.aliased_bytes) / double(std::max<uint64_t>(1, m.lower_bound_bytes));
  state.counters["barriers"] = double(plan.barriers.size());
}

void BM_BuildAndCompile(benchmark::State& state) {
  const Recipe& r = recipe(uint32_t(state.range(0)));
  Plan plan;
  for (auto _ : state) {
    Graph g = rebuild(r);
    plan = compile(g);
    benchmark::DoNotOptimize(plan.order.data());
  }
  report_memory(state, plan);
  state.counters["live_passes"] = double(plan.order.size());
  state.counters["ns_per_pass"] = benchmark::Counter(double(state.range(0)) * double(state.iterations()),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BuildAndCompile)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_CompileOnly(benchmark::State& state) {
  const Recipe& r = recipe(uint32_t(state.range(0)));
  for (auto _ : state) {
    Plan plan = compile(r.source.graph);
    benchmark::DoNotOptimize(plan.order.data());
  }
}
BENCHMARK(BM_CompileOnly)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

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
  // Medians over repeated runs unless the caller asks for something else.
  std::vector<char*> args(argv, argv + argc);
  char repetitions[] = "--benchmark_repetitions=7";
  char aggregates[] = "--benchmark_report_aggregates_only=true";
  if (argc == 1) {
    args.push_back(repetitions);
    args.push_back(aggregates);
  }
  int n = int(args.size());
  benchmark::Initialize(&n, args.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
