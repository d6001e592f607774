// A random graph recorded as the GraphBuilder calls that made it, so that a benchmark
// can time building a graph (bench/bench_compile.cpp) and a test can check that the
// replay builds the very graph it recorded (tests/unit/graph_recipe_test.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "graph/graph.h"
#include "tests/support/random_graph.h"

namespace volgraph::test {

// The benchmark's two shapes of random graph. Frame-like: the scene has every feature,
// inputs take what no pass has read yet (else mostly the last 8 passes, at most 64
// back), so that every pass feeds the frame's outputs. Stress: the property tests'
// shape — random scene needs (most passes get culled), long-range reads from anywhere.
enum class BenchShape { frame_like, stress };

RandomGraphOptions bench_graph_options(uint32_t passes, BenchShape shape);

// One GraphBuilder call after the add_pass calls.
struct BuildStep {
  SlotDirection direction;  // output: create, inout: modify, input: read, history: read_history
  uint16_t slot;
  uint32_t pass;
  ResourceVersion what;     // what it reads or modifies; read_history: the output followed
  uint32_t made = kNone;    // create, read_history: the resource id it must hand out
};

struct GraphRecipe {
  RandomGraph source;
  std::vector<BuildStep> steps;  // in the order the passes made their resources
};

// Records the builder calls that make `source` again, passes in the order they made
// their resources (the builder hands out resource ids in that order, so the replay
// gives every resource its id again). Throws std::invalid_argument for a pass that
// makes no resource: its place in the replay would be unknown.
GraphRecipe record_recipe(RandomGraph source);

// Replays the recorded calls; the result equals the recipe's source graph. Throws
// std::logic_error if the builder hands out another id than the source's.
Graph rebuild(const GraphRecipe& recipe);

}  // namespace volgraph::test
