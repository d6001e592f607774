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
#include "tests/support/random_graph.h"

namespace volgraph {
namespace {

// A recorded graph: rebuilding it replays the GraphBuilder calls that made it, in an
// order where every resource exists before it is read. This is the "building" half of
// the measurement; the random generation that chose the graph is not timed.
struct Recipe {
  test::RandomGraph source;
  std::vector<uint32_t> build_order;
  std::vector<uint32_t> version_begin;  // resource r's versions start here in a flat array
};

// Two shapes of random graph. Frame-like: the scene has every feature, inputs come
// mostly from the last 8 passes and at most 64 back, 2 % of resources are graph
// outputs. Stress: the property tests' shape — random scene needs (most passes get
// culled), long-range reads from anywhere in the frame, 5 % outputs.
enum class Shape { frame_like, stress };

Recipe record(uint32_t passes, Shape shape) {
  test::RandomGraphOptions o;
  o.passes = passes;
  o.seed = 20261121 + passes;
  if (shape == Shape::frame_like) {
    o.allow_needs = false;
    o.far_window = 64;
    o.output_fraction = 0.02;
  }
  Recipe r{test::make_random_graph(o), {}, {}};
  const Plan all = compile(r.source.graph, {.cull = false});
  for (const PlannedPass& p : all.order) r.build_order.push_back(p.pass);
  r.version_begin.push_back(0);
  for (const GraphResource& res : r.source.graph.resources) {
    r.version_begin.push_back(r.version_begin.back() + uint32_t(res.version_writers.size()));
  }
  return r;
}

Graph rebuild(const Recipe& r) {
  const Graph& g = r.source.graph;
  GraphBuilder b(g.output_size, g.scene);
  for (const GraphPass& p : g.passes) b.add_pass(p.name, *p.decl, p.variant);
  std::vector<ResourceVersion> made(r.version_begin.back());  // what the builder returned per version
  auto version = [&](uint32_t res, uint32_t v) -> ResourceVersion& { return made[r.version_begin[res] + v]; };
  for (uint32_t p : r.build_order) {
    for (const ResourceUse& u : g.passes[p].uses) {
      if (u.direction == SlotDirection::output) {
        version(u.resource, 0) = b.create(p, u.slot, g.resources[u.resource].desc);
      } else if (u.direction == SlotDirection::inout) {
        version(u.resource, u.version + 1) = b.modify(p, u.slot, version(u.resource, u.version));
      } else {
        b.read(p, u.slot, version(u.resource, u.version));
      }
    }
  }
  for (const ResourceVersion& o : g.outputs) b.mark_output(version(o.resource, o.version));
  return b.finish();
}

const Recipe& recipe(uint32_t passes, Shape shape) {
  static std::map<std::pair<uint32_t, Shape>, Recipe> cache;  // generated once per size and shape
  auto it = cache.find({passes, shape});
  if (it == cache.end()) it = cache.emplace(std::pair{passes, shape}, record(passes, shape)).first;
  return it->second;
}

void report_memory(benchmark::State& state, const Plan& plan) {
  const MemoryStats& m = plan.memory;
  state.counters["aliasing_saving_%"] = 100.0 * (1.0 - double(m.aliased_bytes) / double(std::max<uint64_t>(1, m.unaliased_bytes)));
  state.counters["aliased/lower_bound"] = double(m.aliased_bytes) / double(std::max<uint64_t>(1, m.lower_bound_bytes));
  state.counters["barriers"] = double(plan.barriers.size());
}

void build_and_compile(benchmark::State& state, Shape shape) {
  const Recipe& r = recipe(uint32_t(state.range(0)), shape);
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
  state.SetLabel(std::string(placement_method_name(plan.memory.method)));
}

void BM_BuildAndCompile_FrameLike(benchmark::State& state) { build_and_compile(state, Shape::frame_like); }
void BM_BuildAndCompile_Stress(benchmark::State& state) { build_and_compile(state, Shape::stress); }
BENCHMARK(BM_BuildAndCompile_FrameLike)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BuildAndCompile_Stress)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_CompileOnly_FrameLike(benchmark::State& state) {
  const Recipe& r = recipe(uint32_t(state.range(0)), Shape::frame_like);
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
