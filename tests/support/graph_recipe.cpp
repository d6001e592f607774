#include "tests/support/graph_recipe.h"

#include <stdexcept>
#include <string>

namespace volgraph::test {

RandomGraphOptions bench_graph_options(uint32_t passes, BenchShape shape) {
  RandomGraphOptions o;
  o.passes = passes;
  o.seed = 20261121 + passes;
  if (shape == BenchShape::frame_like) {
    o.allow_needs = false;
    o.far_window = 64;
    o.output_fraction = 0.02;
    o.consume_unread = true;
  }
  return o;
}

namespace {

// The pass that made resource r: its creator, or for a history the pass reading it
// (which creates the output the history follows).
uint32_t maker_of(const Graph& g, uint32_t r) {
  const GraphResource& res = g.resources[r];
  return res.previous_of != kNone ? g.resources[res.previous_of].creator : res.creator;
}

}  // namespace

GraphRecipe record_recipe(RandomGraph source) {
  GraphRecipe recipe{std::move(source), {}};
  const Graph& g = recipe.source.graph;
  std::vector<uint8_t> placed(g.passes.size(), 0);
  for (uint32_t r = 0; r < g.resources.size(); ++r) {
    const uint32_t p = maker_of(g, r);
    if (p == kNone || placed[p]) continue;
    placed[p] = 1;
    for (const ResourceUse& u : g.passes[p].uses) {
      BuildStep step{u.direction, u.slot, p, {u.resource, u.version}};
      if (u.direction == SlotDirection::output) step.made = u.resource;
      if (u.direction == SlotDirection::history) {  // follows the pass's output, makes the history
        step.what = {g.resources[u.resource].previous_of, 0};
        step.made = u.resource;
      }
      recipe.steps.push_back(step);
    }
  }
  for (uint32_t p = 0; p < g.passes.size(); ++p) {
    if (!placed[p]) throw std::invalid_argument("record_recipe: pass '" + g.passes[p].name + "' makes no resource");
  }
  return recipe;
}

Graph rebuild(const GraphRecipe& recipe) {
  const Graph& g = recipe.source.graph;
  GraphBuilder b(g.output_size, g.scene);
  b.reserve(uint32_t(g.passes.size()), uint32_t(g.resources.size()));
  for (const GraphPass& p : g.passes) b.add_pass(p.name, *p.decl, p.variant);
  auto expect = [](ResourceVersion got, uint32_t resource) {
    if (got.resource != resource) throw std::logic_error("rebuild: the builder handed out another resource id");
  };
  for (const BuildStep& s : recipe.steps) {
    switch (s.direction) {
      case SlotDirection::output:
        expect(b.create(s.pass, s.slot, g.resources[s.made].desc), s.made);
        break;
      case SlotDirection::inout:
        b.modify(s.pass, s.slot, s.what);
        break;
      case SlotDirection::input:
        b.read(s.pass, s.slot, s.what);
        break;
      case SlotDirection::history:
        expect(b.read_history(s.pass, s.slot, s.what), s.made);
        break;
      case SlotDirection::internal:  // never wired into a graph
        break;
    }
  }
  for (const ResourceVersion& o : g.outputs) b.mark_output(o);
  return b.finish();
}

}  // namespace volgraph::test
