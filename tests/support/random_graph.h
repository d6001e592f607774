// Test support: reproducible random render graphs, and a small helper to sketch graphs
// by hand. Everything here is driven by an explicit seed through std::mt19937_64 and
// our own integer helpers, so a seed gives the same graph with every standard library.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "graph/graph.h"
#include "graph/pass_decl.h"

namespace volgraph::test {

// A graph together with the pass declarations its passes point at. The decls live on the
// heap, so moving a RandomGraph keeps every GraphPass::decl valid.
struct RandomGraph {
  std::vector<std::unique_ptr<PassDecl>> decls;
  Graph graph;
};

struct RandomGraphOptions {
  uint32_t passes = 16;
  uint64_t seed = 1;
  uint32_t locality = 8;          // inputs mostly come from the last `locality` passes
  double output_fraction = 0.05;  // chance that a resource's latest version is a graph output
  bool allow_needs = true;        // decls may need scene features (and the scene lacks some)
  bool allow_inout = true;        // decls may have an inout slot
  bool allow_persistent = true;   // outputs may be persistent
  double stale_fraction = 0.05;   // chance per input slot to read an older version when acyclic
  uint32_t far_window = 0;        // long-range reads reach at most this many passes back (0: anywhere)
  // Inputs and inouts take the oldest resource (within far_window) whose latest version
  // no pass has read yet and whose writer feeds no later pass yet, when one fits, and
  // what a pass feeding no later pass leaves unread (the frame's last passes, mostly)
  // becomes a graph output: as in a frame, every pass feeds what the frame delivers.
  bool consume_unread = false;
};

// Builds a random acyclic graph: passes are added in a shuffled order, then wired along a
// hidden topological sequence. Inputs read the latest version of a resource at that point
// of the sequence, except for occasional reads of an older version (the reader must then
// run before the pass that made the next version), made only when they close no cycle.
RandomGraph make_random_graph(const RandomGraphOptions& options);

// Deterministic random helpers (no std::uniform_*_distribution: its output is not
// specified across standard libraries).
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}
  uint64_t next() { return engine_(); }
  // Uniform in [0, n); n > 0.
  uint64_t below(uint64_t n);
  // Uniform in [lo, hi] (inclusive).
  int64_t range(int64_t lo, int64_t hi) { return lo + static_cast<int64_t>(below(static_cast<uint64_t>(hi - lo) + 1)); }
  // Uniform in [0, 1).
  double unit() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
  bool chance(double p) { return unit() < p; }
  template <typename T>
  const T& pick(const std::vector<T>& items) { return items[below(items.size())]; }
  template <typename T>
  void shuffle(std::vector<T>& items) {
    for (size_t i = items.size(); i > 1; --i) {
      const size_t j = below(i);
      std::swap(items[i - 1], items[j]);
    }
  }

 private:
  std::mt19937_64 engine_;
};

// Sketching a small graph by hand: each pass gets its own decl made from a slot list.
//
//   GraphSketch s;
//   auto w = s.pass("write", PassKind::compute, {out_slot("o", ResourceKind::buffer, Usage::storage_write,
//                                                          Format::undefined, SizeSpec::bytes(1024))});
//   auto t = s.out(w, "o");
//   ...
//   RandomGraph g = s.finish();
class GraphSketch {
 public:
  explicit GraphSketch(Extent output_size = {256, 256, 1}, SceneFeatures scene = ~SceneFeatures{0});

  uint32_t pass(std::string name, PassKind kind, std::vector<SlotDecl> slots, SceneFeatures needs = 0);
  // Binds an output slot to a new resource sized by the slot (resolve_slot).
  ResourceVersion out(uint32_t pass, std::string_view slot);
  void in(uint32_t pass, std::string_view slot, ResourceVersion what);
  ResourceVersion inout(uint32_t pass, std::string_view slot, ResourceVersion what);
  void output(ResourceVersion what);

  GraphBuilder& builder() { return builder_; }
  RandomGraph finish();

 private:
  uint16_t slot_of(uint32_t pass, std::string_view slot);
  std::vector<std::unique_ptr<PassDecl>> decls_;
  GraphBuilder builder_;
};

// Slot shorthands for sketches (outputs, inputs, optional inputs, inouts).
SlotDecl out_slot(std::string name, ResourceKind kind, Usage usage, Format format, SizeSpec size,
                  bool persistent = false);
SlotDecl in_slot(std::string name, ResourceKind kind, Usage usage, bool optional = false);
SlotDecl inout_slot(std::string name, ResourceKind kind, Usage usage);

// Human-readable dumps for failure messages.
std::string graph_text(const Graph& graph);

}  // namespace volgraph::test
