// Barriers: each resource's uses are replayed in plan order and a transition is
// recorded only where one is needed — a layout change, a write after any access, or
// a read of a write not yet made visible to it. A barrier before a read covers every
// read that follows in the same layout until the next write, so reads in other
// stages need no barrier of their own.
#include <algorithm>
#include <span>

#include "graph/compiler/steps.h"

namespace volgraph::compiler {
namespace {

struct Use {
  uint32_t position;
  AccessState state;
};

bool is_write(const AccessState& s) { return (s.access & access::all_writes) != 0; }

// Uses per resource in plan order, as compressed rows: resource r's uses are
// uses[begin[r] .. begin[r + 1]). A pass using one resource in several slots
// contributes one use with their states combined.
struct UsesByResource {
  std::vector<uint32_t> begin;
  std::vector<Use> uses;
  std::span<const Use> of(uint32_t r) const { return {uses.data() + begin[r], uses.data() + begin[r + 1]}; }
};

UsesByResource uses_by_resource(const FlatGraph& g, const Schedule& schedule) {
  UsesByResource out;
  std::vector<uint32_t> last_position(g.resource_count(), kNone);
  auto for_each_bound_use = [&](auto&& visit) {
    for (uint32_t pos = 0; pos < schedule.order.size(); ++pos) {
      const uint32_t p = schedule.order[pos];
      for (uint32_t k = g.use_begin[p]; k < g.use_begin[p + 1]; ++k) {
        if (schedule.bound[k]) visit(pos, g.pass_kind[p], g.uses[k]);
      }
    }
  };
  out.begin.assign(g.resource_count() + 1, 0);
  for_each_bound_use([&](uint32_t pos, PassKind, const ResourceUse& u) {
    if (last_position[u.resource] == pos) return;
    last_position[u.resource] = pos;
    ++out.begin[u.resource + 1];
  });
  for (uint32_t r = 0; r < g.resource_count(); ++r) out.begin[r + 1] += out.begin[r];
  out.uses.resize(out.begin.back());
  std::vector<uint32_t> fill(out.begin.begin(), out.begin.end() - 1);
  std::fill(last_position.begin(), last_position.end(), kNone);
  for_each_bound_use([&](uint32_t pos, PassKind kind, const ResourceUse& u) {
    const AccessState s = access_state(u.usage, kind, g.resource_kind[u.resource]);
    if (last_position[u.resource] == pos) {
      Use& merged = out.uses[fill[u.resource] - 1];
      merged.state.stages |= s.stages;
      merged.state.access |= s.access;
      if (merged.state.layout != s.layout) merged.state.layout = Layout::general;  // the one layout every usage allows
      return;
    }
    last_position[u.resource] = pos;
    out.uses[fill[u.resource]++] = {pos, s};
  });
  return out;
}

// What the resource's last accesses were, for whatever must wait on them.
struct Tracker {
  Layout layout = Layout::undefined;
  uint32_t write_stages = 0;
  uint32_t write_access = 0;
  uint32_t read_stages = 0;      // reads since the last write, not yet waited on
  uint32_t visible_stages = 0;   // where the last write has been made visible
  uint32_t visible_access = 0;
};

// The reads from `i` on that one barrier can serve: same layout, until a write. They
// run on into `next`, the uses the resource's object has next (a history pair's output
// is read as history the next frame).
AccessState read_run(std::span<const Use> uses, size_t i, std::span<const Use> next) {
  AccessState run = uses[i].state;
  bool open = true;
  for (const std::span<const Use> list : {uses.subspan(i + 1), next}) {
    for (size_t j = 0; open && j < list.size(); ++j) {
      open = !is_write(list[j].state) && list[j].state.layout == run.layout;
      if (!open) break;
      run.stages |= list[j].state.stages;
      run.access |= list[j].state.access;
    }
  }
  return run;
}

// Replays one resource's uses from state `t`, appending the barriers it needs (and
// their positions) when `out` is given; returns the state after the last use.
Tracker replay(uint32_t resource, std::span<const Use> uses, std::span<const Use> next, Tracker t, bool fresh,
               bool handed_over, std::vector<Barrier>* out, std::vector<uint32_t>* positions) {
  for (size_t i = 0; i < uses.size(); ++i) {
    const AccessState& s = uses[i].state;
    const bool writes = is_write(s);
    const AccessState dst = writes ? s : read_run(uses, i, next);
    Barrier b{resource, {t.write_stages | t.read_stages, t.write_access, t.layout}, dst, false};
    bool needed;
    if (fresh && i == 0) {
      b.from = {0, 0, s.layout == Layout::none ? Layout::none : Layout::undefined};
      b.aliasing = handed_over;  // its src scope is filled in from the previous occupants
      needed = handed_over || s.layout != Layout::none;
    } else if (s.layout != t.layout) {
      needed = true;
    } else if (writes) {
      needed = (t.write_stages | t.read_stages) != 0;
    } else {
      const bool visible = (s.stages & ~t.visible_stages) == 0 && (s.access & ~t.visible_access) == 0;
      needed = t.write_stages != 0 && !visible;
      b.from = {t.write_stages, t.write_access, t.layout};
    }
    if (fresh && i == 0) t.layout = s.layout;
    if (needed) {
      if (out) {
        out->push_back(b);
        positions->push_back(uses[i].position);
      }
      t.visible_stages = b.to.stages;
      t.visible_access = b.to.access;
      t.layout = s.layout;
      if (b.from.layout != b.to.layout) t.read_stages = 0;
    }
    if (writes) {
      t.write_stages = s.stages;
      t.write_access = s.access & access::all_writes;
      t.read_stages = 0;
      t.visible_stages = t.visible_access = 0;
    } else {
      t.read_stages |= s.stages;
    }
  }
  return t;
}

// A history pair's other resource (kNone for any other resource).
uint32_t partner_of(const GraphResource& r) { return r.previous != kNone ? r.previous : r.previous_of; }

// What resource r's object is used for after this frame's uses: an output with a history
// is read as that history the next frame.
std::span<const Use> next_uses(const Graph& graph, const UsesByResource& uses, uint32_t r) {
  const uint32_t previous = graph.resources[r].previous;
  return previous == kNone ? std::span<const Use>{} : uses.of(previous);
}

// The state persistent resource `r`'s physical object starts a frame in: where the
// last frame left it. A history pair's two objects swap every frame, so r's object was
// its partner's the frame before, and r's the frame before that.
Tracker frame_start(const Graph& graph, const UsesByResource& uses, uint32_t r) {
  const uint32_t partner = partner_of(graph.resources[r]);
  const Tracker own = replay(r, uses.of(r), next_uses(graph, uses, r), Tracker{}, false, false, nullptr, nullptr);
  if (partner == kNone || uses.of(partner).empty()) return own;
  return replay(partner, uses.of(partner), next_uses(graph, uses, partner), own, false, false, nullptr, nullptr);
}

// Before the first frame: the texture from undefined contents into the state the plan
// expects every frame to start in — its layout, visible where the plan assumes the last
// write visible, and ordered before the stages its first barrier waits on.
Barrier initial_barrier(uint32_t r, const Tracker& start) {
  const AccessState undefined{stage::none, access::none, Layout::undefined};
  const AccessState to{start.write_stages | start.read_stages | start.visible_stages, start.write_access | start.visible_access,
                       start.layout};
  return {r, undefined, to, false};
}

}  // namespace

BarrierPlan plan_barriers(const FlatGraph& g, const Schedule& schedule, const std::vector<Handover>& handovers,
                          bool serialize) {
  const Graph& graph = *g.graph;
  const UsesByResource uses = uses_by_resource(g, schedule);
  std::vector<uint8_t> handed_over(graph.resources.size(), 0);
  for (const Handover& h : handovers) handed_over[h.resource] = 1;

  std::vector<Barrier> barriers;
  std::vector<uint32_t> positions;
  barriers.reserve(uses.uses.size());
  positions.reserve(uses.uses.size());
  std::vector<uint32_t> first_barrier(graph.resources.size(), kNone);
  std::vector<Tracker> last_state(graph.resources.size());
  std::vector<Barrier> initial;
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {
    const std::span<const Use> list = uses.of(r);
    if (list.empty()) continue;
    const bool persistent = graph.resources[r].desc.persistent;
    // A persistent resource starts each frame as the previous frame left it.
    const Tracker start = persistent ? frame_start(graph, uses, r) : Tracker{};
    if (persistent && start.layout != Layout::none) initial.push_back(initial_barrier(r, start));
    first_barrier[r] = uint32_t(barriers.size());
    last_state[r] = replay(r, list, next_uses(graph, uses, r), start, !persistent, handed_over[r], &barriers, &positions);
  }
  // The first use after a hand-over waits for every previous occupant's last accesses.
  for (const Handover& h : handovers) {
    const Tracker& prev = last_state[h.previous];
    Barrier& b = barriers[first_barrier[h.resource]];
    b.from.stages |= prev.write_stages | prev.read_stages;
    b.from.access |= prev.write_access;
  }

  const uint32_t n = static_cast<uint32_t>(schedule.order.size());
  BarrierPlan plan;
  plan.begin.assign(n, 0);
  plan.count.assign(n, 0);
  for (uint32_t pos : positions) ++plan.count[pos];
  if (serialize) {
    for (uint32_t pos = 1; pos < n; ++pos) ++plan.count[pos];
  }
  for (uint32_t pos = 1; pos < n; ++pos) plan.begin[pos] = plan.begin[pos - 1] + plan.count[pos - 1];
  plan.barriers.resize(n ? plan.begin[n - 1] + plan.count[n - 1] : 0);
  std::vector<uint32_t> fill(plan.begin);
  if (serialize) {
    const AccessState everything_before{stage::all_commands, access::memory_write, Layout::none};
    const AccessState everything_after{stage::all_commands, access::memory_read | access::memory_write, Layout::none};
    for (uint32_t pos = 1; pos < n; ++pos) plan.barriers[fill[pos]++] = {kNone, everything_before, everything_after, false};
  }
  for (size_t i = 0; i < barriers.size(); ++i) plan.barriers[fill[positions[i]]++] = barriers[i];
  plan.initial = std::move(initial);
  // What follows the frame waits on the last write and every read since (their stages),
  // and finds the resource in its last layout.
  plan.final_states.resize(graph.resources.size());
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {
    if (uses.of(r).empty()) continue;
    const Tracker& t = last_state[r];
    plan.final_states[r] = {t.write_stages | t.read_stages, t.write_access, t.layout};
  }
  return plan;
}

}  // namespace volgraph::compiler
