#include "tests/support/plan_checker.h"

#include <algorithm>
#include <array>
#include <map>
#include <sstream>
#include <unordered_map>

namespace volgraph::test {
namespace {

// ---------------------------------------------------------------------------------------
// Stage and access arithmetic.

constexpr uint32_t kStageCount = 7;  // real stages: bits 0..6; bit 7 is all_commands
constexpr uint32_t kRealStages = (1u << kStageCount) - 1;

constexpr uint32_t kReadBits = access::shader_sampled_read | access::shader_storage_read | access::uniform_read |
                               access::color_attachment_read | access::depth_stencil_read | access::transfer_read;
constexpr uint32_t kWriteBits = access::shader_storage_write | access::color_attachment_write |
                                access::depth_stencil_write | access::transfer_write;

// all_commands stands for every stage.
uint32_t norm_stages(uint32_t s) { return (s & stage::all_commands) ? kRealStages : (s & kRealStages); }

// memory_read / memory_write stand for every read / write access.
uint32_t norm_access(uint32_t a) {
  uint32_t r = a & (kReadBits | kWriteBits);
  if (a & access::memory_read) r |= kReadBits;
  if (a & access::memory_write) r |= kWriteBits;
  return r;
}

// The graphics pipeline's logical order; compute and copy stand alone. A barrier's first
// execution scope includes logically earlier stages, its second logically later ones.
constexpr std::array<uint32_t, 5> kGraphicsOrder = {stage::vertex_shader, stage::early_fragment_tests,
                                                    stage::fragment_shader, stage::late_fragment_tests,
                                                    stage::color_attachment_output};

uint32_t expand_src(uint32_t s) {
  s = norm_stages(s);
  uint32_t out = s;
  uint32_t earlier = 0;
  for (uint32_t g : kGraphicsOrder) {
    if (s & g) out |= earlier;
    earlier |= g;
  }
  return out;
}

uint32_t expand_dst(uint32_t s) {
  s = norm_stages(s);
  uint32_t out = s;
  uint32_t later = 0;
  for (size_t i = kGraphicsOrder.size(); i-- > 0;) {
    if (s & kGraphicsOrder[i]) out |= later;
    later |= kGraphicsOrder[i];
  }
  return out;
}

bool covers(uint32_t have, uint32_t need) { return (need & ~have) == 0; }

// ---------------------------------------------------------------------------------------

struct PassUse {  // everything one live pass does to one resource, combined
  uint32_t resource = kNone;
  AccessState state{};
  uint32_t reads = 0;   // normalised read access bits
  uint32_t writes = 0;  // normalised write access bits
};

struct RState {  // synchronisation state of one resource during the replay
  Layout layout = Layout::undefined;
  bool accessed = false;     // any use or barrier so far (this frame, or the last one in steady state)
  bool written = false;      // a last write exists (a use that wrote, or a layout transition)
  uint32_t w_stages = 0;     // its stages
  uint32_t w_access = 0;     // its write access bits (none for a transition)
  bool w_available = false;  // made available by a barrier whose access scope covered it
  uint32_t w_before = 0;     // stages it is ordered before
  std::array<uint32_t, kStageCount> vis{};  // per stage: the access bits it is visible to
  uint32_t read_stages = 0;  // stages that read since the last write
  std::array<uint32_t, kStageCount> read_before{};  // per read stage: stages those reads are ordered before
  bool content_valid = false;  // false after a discard (or before anything was written)
  bool have_last_use = false;
  bool last_use_read_only = false;
  Layout last_use_layout = Layout::undefined;
  bool first_use_done = false;
};

struct Event {
  uint32_t pos;
  bool is_use;
  uint32_t index;  // barrier index, or index into uses_at[pos]
};

struct GlobalBarrier {
  uint32_t pos;
  uint32_t index;
};

class Checker {
 public:
  Checker(const Graph& g, const Plan& plan, const CompileOptions& options, const RequirementsFn& req)
      : g_(g), plan_(plan), opt_(options), req_(req ? req : RequirementsFn([](uint32_t, const ResourceDesc& d) { return estimate_requirements(d); })) {}

  std::vector<std::string> run() {
    if (!check_shapes()) return std::move(out_);
    if (!model_culling()) return std::move(out_);
    check_culling();
    if (!check_order()) return std::move(out_);
    collect_uses();
    check_dependencies();
    check_lifetimes();
    check_memory();
    check_handovers();
    check_barriers();
    return std::move(out_);
  }

  // Exposed through expected_culling().
  bool model_culling();
  std::vector<bool> live_;
  std::vector<std::optional<CullReason>> reason_;

 private:
  // ----- reporting
  static constexpr size_t kMaxReports = 400;
  void fail(const std::string& rule, const std::string& what) {
    if (out_.size() < kMaxReports) {
      out_.push_back("[" + rule + "] " + what);
    } else if (out_.size() == kMaxReports) {
      out_.push_back("... more violations not shown");
    }
  }
  std::string pn(uint32_t p) const {
    if (p >= g_.passes.size()) return "pass #" + std::to_string(p) + " (out of range)";
    return "pass '" + g_.passes[p].name + "' (#" + std::to_string(p) + ")";
  }
  std::string rn(uint32_t r) const {
    if (r >= g_.resources.size()) return "resource #" + std::to_string(r) + " (out of range)";
    return "resource '" + g_.resources[r].desc.name + "' (#" + std::to_string(r) + ")";
  }
  std::string at(uint32_t pos) const {
    return pn(plan_.order[pos].pass) + " at position " + std::to_string(pos);
  }
  static std::string state_text(const AccessState& s) {
    return stage_names(s.stages) + "/" + access_names(s.access) + "/" + std::string(layout_name(s.layout));
  }
  static std::string barrier_text(const Barrier& b) {
    return "{" + state_text(b.from) + " -> " + state_text(b.to) + (b.aliasing ? ", aliasing" : "") + "}";
  }

  bool is_image(uint32_t r) const { return g_.resources[r].desc.kind != ResourceKind::buffer; }
  uint32_t writer(uint32_t r, uint32_t v) const { return g_.resources[r].version_writers[v]; }

  // The version a reader of (r, v) really sees: need-culled writers forward their input.
  // -1 when that version does not exist.
  int64_t effective(uint32_t r, uint32_t v) const {
    if (!opt_.cull) return v;
    for (;;) {
      if (writer(r, v) == kNone) return v;  // a history: made by the last frame, always there
      if (!need_culled_[writer(r, v)]) return v;
      if (v == 0) return -1;
      --v;
    }
  }

  bool check_shapes();
  void check_culling();
  bool check_order();
  void collect_uses();
  void check_dependencies();
  void check_lifetimes();
  void check_memory();
  void check_handovers();
  void check_barriers();
  const PassUse* use_of(uint32_t pos, uint32_t r) const;
  void replay(uint32_t r, RState& st, bool report, const std::string& tag);
  void replay_frames(uint32_t r);
  void apply_barrier(uint32_t r, RState& st, const Barrier& b, uint32_t pos, bool report, const std::string& tag);
  void apply_use(uint32_t r, RState& st, const PassUse& u, uint32_t pos, bool report, const std::string& tag);

  const Graph& g_;
  const Plan& plan_;
  const CompileOptions& opt_;
  RequirementsFn req_;
  std::vector<std::string> out_;

  std::vector<uint32_t> topo_;
  std::vector<bool> need_failed_;   // own needs fail
  std::vector<bool> need_culled_;   // needs fail or a required input does not exist
  std::vector<std::vector<PassUse>> uses_at_;  // per position, sorted by resource
  std::vector<Lifetime> life_;                 // expected lifetimes
  std::vector<MemoryRequirements> reqs_;       // expected requirements of used resources
  std::vector<std::pair<uint32_t, uint32_t>> alias_pairs_;  // (earlier, later) sharing bytes
  std::vector<std::vector<uint32_t>> handed_from_;          // per resource: handover previous list
  std::vector<std::vector<Event>> events_;                  // per resource: its barriers and uses in order
  std::vector<GlobalBarrier> globals_;
  std::vector<size_t> global_run_end_;  // per global barrier: index after its run of identical ones
};

// ---------------------------------------------------------------------------------------

bool Checker::check_shapes() {
  bool ok = true;
  for (size_t p = 0; p < g_.passes.size(); ++p) {
    for (const ResourceUse& u : g_.passes[p].uses) {
      if (u.resource >= g_.resources.size() || u.version >= g_.resources[u.resource].version_writers.size()) {
        fail("graph", pn(uint32_t(p)) + " uses a resource version that does not exist");
        ok = false;
      }
    }
  }
  for (size_t r = 0; r < g_.resources.size(); ++r) {
    const GraphResource& res = g_.resources[r];
    if (res.previous_of != kNone) {  // a history: one version, made by the last frame
      const bool paired = res.previous_of < g_.resources.size() && g_.resources[res.previous_of].previous == r;
      if (!paired || res.version_writers != std::vector<uint32_t>{kNone} || !res.desc.persistent ||
          !g_.resources[res.previous_of].desc.persistent) {
        fail("graph", rn(uint32_t(r)) + " is a history but not one persistent version paired with its output");
        ok = false;
      }
      continue;
    }
    for (uint32_t w : res.version_writers) {
      if (w >= g_.passes.size()) {
        fail("graph", rn(uint32_t(r)) + " has a version writer out of range");
        ok = false;
      }
    }
    if (g_.resources[r].version_writers.empty()) {
      fail("graph", rn(uint32_t(r)) + " has no versions");
      ok = false;
    }
  }
  for (const ResourceVersion& o : g_.outputs) {
    if (o.resource >= g_.resources.size() || o.version >= g_.resources[o.resource].version_writers.size()) {
      fail("graph", "a graph output names a resource version that does not exist");
      ok = false;
    }
  }
  if (plan_.options.cull != opt_.cull || plan_.options.alias != opt_.alias ||
      plan_.options.serialize != opt_.serialize) {
    fail("shape", "plan.options differ from the options the plan was compiled with");
  }
  if (plan_.position.size() != g_.passes.size()) {
    fail("shape", "plan.position has " + std::to_string(plan_.position.size()) + " entries for " +
                      std::to_string(g_.passes.size()) + " passes");
    ok = false;
  }
  if (plan_.lifetimes.size() != g_.resources.size()) {
    fail("shape", "plan.lifetimes has " + std::to_string(plan_.lifetimes.size()) + " entries for " +
                      std::to_string(g_.resources.size()) + " resources");
    ok = false;
  }
  if (plan_.placements.size() != g_.resources.size()) {
    fail("shape", "plan.placements has " + std::to_string(plan_.placements.size()) + " entries for " +
                      std::to_string(g_.resources.size()) + " resources");
    ok = false;
  }
  for (size_t i = 0; i < plan_.order.size(); ++i) {
    const PlannedPass& pp = plan_.order[i];
    if (pp.pass >= g_.passes.size()) {
      fail("shape", "order[" + std::to_string(i) + "] names pass #" + std::to_string(pp.pass) + ", out of range");
      ok = false;
    }
    if (uint64_t{pp.barrier_begin} + pp.barrier_count > plan_.barriers.size()) {
      fail("shape", "order[" + std::to_string(i) + "] has a barrier range outside plan.barriers");
      ok = false;
    }
  }
  for (size_t k = 0; k < plan_.barriers.size(); ++k) {
    const uint32_t r = plan_.barriers[k].resource;
    if (r != kNone && r >= g_.resources.size()) {
      fail("shape", "barrier " + std::to_string(k) + " names resource #" + std::to_string(r) + ", out of range");
      ok = false;
    }
  }
  return ok;
}

bool Checker::model_culling() {
  const size_t n = g_.passes.size();
  // A topological order over "produces a version read by" edges (Kahn).
  std::vector<std::vector<uint32_t>> succ(n);
  std::vector<uint32_t> indeg(n, 0);
  for (uint32_t p = 0; p < n; ++p) {
    for (const ResourceUse& u : g_.passes[p].uses) {
      if (u.direction == SlotDirection::output || u.direction == SlotDirection::history) continue;
      const uint32_t w = writer(u.resource, u.version);
      succ[w].push_back(p);
      ++indeg[p];
    }
  }
  std::vector<uint32_t> ready;
  for (uint32_t p = 0; p < n; ++p) {
    if (indeg[p] == 0) ready.push_back(p);
  }
  topo_.clear();
  while (!ready.empty()) {
    const uint32_t p = ready.back();
    ready.pop_back();
    topo_.push_back(p);
    for (uint32_t s : succ[p]) {
      if (--indeg[s] == 0) ready.push_back(s);
    }
  }
  if (topo_.size() != n) {
    fail("graph", "the graph has a cycle through producer edges, yet compile() returned a plan");
    return false;
  }

  need_failed_.assign(n, false);
  need_culled_.assign(n, false);
  reason_.assign(n, std::nullopt);
  live_.assign(n, !opt_.cull);
  if (!opt_.cull) return true;

  for (uint32_t p : topo_) {
    const GraphPass& pass = g_.passes[p];
    const bool lacks_any = pass.needs_any != 0 && (pass.needs_any & g_.scene) == 0;
    if ((pass.needs & ~g_.scene) != 0 || lacks_any) {
      need_failed_[p] = true;
      need_culled_[p] = true;
      reason_[p] = CullReason::scene_lacks;
      continue;
    }
    for (const ResourceUse& u : pass.uses) {
      if (u.direction == SlotDirection::output) continue;
      if (u.direction == SlotDirection::input && u.optional) continue;
      if (effective(u.resource, u.version) < 0) {
        need_culled_[p] = true;
        reason_[p] = CullReason::input_culled;
        break;
      }
    }
  }
  // Live: reachable backwards from the graph outputs through effective producers.
  std::vector<uint32_t> stack;
  auto reach = [&](uint32_t r, uint32_t v) {
    const int64_t e = effective(r, v);
    if (e < 0) return;
    const uint32_t w = writer(r, static_cast<uint32_t>(e));
    if (w == kNone) return;  // made by the last frame
    if (!live_[w]) {
      live_[w] = true;
      stack.push_back(w);
    }
  };
  for (const ResourceVersion& o : g_.outputs) reach(o.resource, o.version);
  while (!stack.empty()) {
    const uint32_t p = stack.back();
    stack.pop_back();
    for (const ResourceUse& u : g_.passes[p].uses) {
      if (u.direction != SlotDirection::output && u.direction != SlotDirection::history) reach(u.resource, u.version);
    }
  }
  for (uint32_t p = 0; p < n; ++p) {
    if (!live_[p] && !reason_[p]) reason_[p] = CullReason::unused;
    if (live_[p]) reason_[p] = std::nullopt;
  }
  return true;
}

void Checker::check_culling() {
  const size_t n = g_.passes.size();
  std::vector<int> listed(n, 0);
  for (const CulledPass& c : plan_.culled) {
    if (c.pass >= n) {
      fail("cull", "plan.culled names pass #" + std::to_string(c.pass) + ", out of range");
      continue;
    }
    if (++listed[c.pass] == 2) fail("cull", pn(c.pass) + " is listed twice in plan.culled");
    if (live_[c.pass]) {
      fail("cull", pn(c.pass) + " is culled (" + std::string(cull_reason_name(c.reason)) +
                       ") but must run" + (opt_.cull ? " (it reaches a graph output)" : " (culling is off)"));
    } else if (reason_[c.pass] && *reason_[c.pass] != c.reason) {
      fail("cull-reason", pn(c.pass) + " is culled as " + std::string(cull_reason_name(c.reason)) + ", expected " +
                              std::string(cull_reason_name(*reason_[c.pass])));
    }
  }
  for (uint32_t p = 0; p < n; ++p) {
    if (!live_[p] && listed[p] == 0) {
      fail("cull", pn(p) + " must be culled (" + std::string(cull_reason_name(*reason_[p])) +
                       ") but is not in plan.culled");
    }
  }
}

bool Checker::check_order() {
  const size_t n = g_.passes.size();
  bool ok = true;
  std::vector<int> seen(n, 0);
  for (size_t i = 0; i < plan_.order.size(); ++i) {
    const uint32_t p = plan_.order[i].pass;
    if (++seen[p] == 2) {
      fail("order", pn(p) + " appears twice in plan.order");
      ok = false;
    }
    if (!live_[p]) {
      fail("order", pn(p) + " is in plan.order but must be culled");
      ok = false;
    }
    if (plan_.position[p] != i) {
      fail("order", "plan.position of " + pn(p) + " is " + std::to_string(plan_.position[p]) + " but it runs at " +
                        std::to_string(i));
    }
  }
  for (uint32_t p = 0; p < n; ++p) {
    if (live_[p] && seen[p] == 0) {
      fail("order", pn(p) + " must run but is not in plan.order");
      ok = false;
    }
    if (!live_[p] && plan_.position[p] != kNone) {
      fail("order", "plan.position of culled " + pn(p) + " is not kNone");
    }
  }
  return ok;
}

void Checker::collect_uses() {
  uses_at_.assign(plan_.order.size(), {});
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const uint32_t p = plan_.order[pos].pass;
    const GraphPass& pass = g_.passes[p];
    std::vector<PassUse>& uses = uses_at_[pos];
    for (const ResourceUse& u : pass.uses) {
      if (u.direction != SlotDirection::output && effective(u.resource, u.version) < 0) continue;  // absent optional
      const AccessState s = access_state(u.usage, pass.kind, g_.resources[u.resource].desc.kind);
      auto it = std::find_if(uses.begin(), uses.end(), [&](const PassUse& x) { return x.resource == u.resource; });
      if (it == uses.end()) {
        PassUse pu;
        pu.resource = u.resource;
        pu.state = s;
        uses.push_back(pu);
        it = uses.end() - 1;
      } else {
        // One image in two slots wanting different layouts: only `general` serves every
        // usage at once (Vulkan allows sampling, storage, attachment and copy in it).
        if (it->state.layout != s.layout) it->state.layout = Layout::general;
        it->state.stages |= s.stages;
        it->state.access |= s.access;
      }
    }
    for (PassUse& pu : uses) {
      pu.reads = norm_access(pu.state.access) & kReadBits;
      pu.writes = norm_access(pu.state.access) & kWriteBits;
    }
    std::sort(uses.begin(), uses.end(), [](const PassUse& a, const PassUse& b) { return a.resource < b.resource; });
  }
}

const PassUse* Checker::use_of(uint32_t pos, uint32_t r) const {
  const std::vector<PassUse>& uses = uses_at_[pos];
  auto it = std::lower_bound(uses.begin(), uses.end(), r, [](const PassUse& u, uint32_t x) { return u.resource < x; });
  return (it != uses.end() && it->resource == r) ? &*it : nullptr;
}

void Checker::check_dependencies() {
  // Readers of each (resource, effective version), among live passes.
  std::unordered_map<uint64_t, std::vector<uint32_t>> readers;
  auto key = [](uint32_t r, int64_t v) { return (uint64_t{r} << 32) | static_cast<uint32_t>(v); };
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const uint32_t p = plan_.order[pos].pass;
    for (const ResourceUse& u : g_.passes[p].uses) {
      if (u.direction == SlotDirection::output || u.direction == SlotDirection::history) continue;
      const int64_t e = effective(u.resource, u.version);
      if (e < 0) continue;
      readers[key(u.resource, e)].push_back(p);
      const uint32_t w = writer(u.resource, static_cast<uint32_t>(e));
      const uint32_t wpos = plan_.position[w];
      if (wpos == kNone || wpos >= pos) {
        fail("order", pn(p) + " reads " + rn(u.resource) + " version " + std::to_string(e) + " made by " + pn(w) +
                          (wpos == kNone ? ", which does not run" : ", but runs before it"));
      }
    }
  }
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const uint32_t p = plan_.order[pos].pass;
    for (const ResourceUse& u : g_.passes[p].uses) {
      if (u.direction != SlotDirection::inout) continue;
      const int64_t e = effective(u.resource, u.version);
      if (e < 0) continue;
      auto it = readers.find(key(u.resource, e));
      if (it == readers.end()) continue;
      for (uint32_t q : it->second) {
        if (q == p) continue;
        if (plan_.position[q] >= pos) {
          fail("order", pn(p) + " overwrites " + rn(u.resource) + " version " + std::to_string(e) + " before " +
                            pn(q) + " reads it (write after read)");
        }
      }
    }
  }
}

void Checker::check_lifetimes() {
  const uint32_t n = static_cast<uint32_t>(plan_.order.size());
  life_.assign(g_.resources.size(), Lifetime{});
  for (uint32_t pos = 0; pos < n; ++pos) {
    for (const PassUse& u : uses_at_[pos]) {
      Lifetime& l = life_[u.resource];
      if (l.first == kNone) l.first = pos;
      l.last = pos;
    }
  }
  for (const ResourceVersion& o : g_.outputs) {
    if (effective(o.resource, o.version) >= 0 && life_[o.resource].first != kNone) life_[o.resource].last = n;
  }
  for (uint32_t r = 0; r < g_.resources.size(); ++r) {
    const Lifetime& want = life_[r];
    const Lifetime& got = plan_.lifetimes[r];
    if (want.first == kNone) {
      if (got.first != kNone) fail("lifetime", rn(r) + " has no live use but its lifetime starts at " + std::to_string(got.first));
      continue;
    }
    if (got.first != want.first || got.last != want.last) {
      auto txt = [](const Lifetime& l) {
        return "[" + (l.first == kNone ? std::string("none") : std::to_string(l.first)) + ", " +
               (l.last == kNone ? std::string("none") : std::to_string(l.last)) + "]";
      };
      fail("lifetime", rn(r) + " has lifetime " + txt(got) + ", expected " + txt(want));
    }
  }
}

void Checker::check_memory() {
  const size_t nr = g_.resources.size();
  const uint32_t n = static_cast<uint32_t>(plan_.order.size());
  reqs_.assign(nr, MemoryRequirements{});
  uint64_t unaliased = 0, persistent = 0, transient_count = 0;
  std::map<uint32_t, std::vector<int64_t>> diff;  // per heap class: size deltas over positions
  for (uint32_t r = 0; r < nr; ++r) {
    const GraphResource& res = g_.resources[r];
    const Placement& pl = plan_.placements[r];
    if (res.desc.persistent && pl.heap != kNone) {
      fail("memory", "persistent " + rn(r) + " is placed in heap " + std::to_string(pl.heap) + " (must not alias)");
    }
    if (life_[r].first == kNone) {
      // Unused: it takes no bytes that matter, but a placement must still be valid.
      if (pl.heap != kNone && (pl.heap >= plan_.heaps.size() ||
                               pl.offset + pl.requirements.size > plan_.heaps[pl.heap].size)) {
        fail("memory", "unused " + rn(r) + " has a placement outside heap " + std::to_string(pl.heap));
      }
      continue;
    }
    const MemoryRequirements m = req_(r, res.desc);
    reqs_[r] = m;
    if (pl.requirements.size != m.size || pl.requirements.alignment != m.alignment ||
        pl.requirements.heap_class != m.heap_class) {
      fail("memory", rn(r) + " placement requirements (" + std::to_string(pl.requirements.size) + " B, align " +
                         std::to_string(pl.requirements.alignment) + ", class " +
                         std::to_string(pl.requirements.heap_class) + ") differ from the requirements function (" +
                         std::to_string(m.size) + " B, align " + std::to_string(m.alignment) + ", class " +
                         std::to_string(m.heap_class) + ")");
    }
    if (res.desc.persistent) {
      persistent += m.size;
      continue;
    }
    unaliased += m.size;
    ++transient_count;
    auto& d = diff[m.heap_class];
    if (d.empty()) d.assign(n + 2, 0);
    d[life_[r].first] += static_cast<int64_t>(m.size);
    d[life_[r].last + 1] -= static_cast<int64_t>(m.size);
    if (pl.heap == kNone) continue;
    if (pl.heap >= plan_.heaps.size()) {
      fail("memory", rn(r) + " is placed in heap " + std::to_string(pl.heap) + ", which does not exist");
      continue;
    }
    const Heap& h = plan_.heaps[pl.heap];
    if (h.heap_class != m.heap_class) {
      fail("memory", rn(r) + " of heap class " + std::to_string(m.heap_class) + " is placed in heap " +
                         std::to_string(pl.heap) + " of class " + std::to_string(h.heap_class));
    }
    if (m.alignment > 1 && pl.offset % m.alignment != 0) {
      fail("memory", rn(r) + " offset " + std::to_string(pl.offset) + " is not a multiple of its alignment " +
                         std::to_string(m.alignment));
    }
    if (m.alignment > 1 && (h.alignment == 0 || h.alignment % m.alignment != 0)) {
      fail("memory", "heap " + std::to_string(pl.heap) + " alignment " + std::to_string(h.alignment) +
                         " does not satisfy " + rn(r) + "'s alignment " + std::to_string(m.alignment));
    }
    if (pl.offset + m.size > h.size || pl.offset + m.size < pl.offset) {
      fail("memory", rn(r) + " [" + std::to_string(pl.offset) + ", +" + std::to_string(m.size) +
                         ") does not fit heap " + std::to_string(pl.heap) + " of " + std::to_string(h.size) + " B");
    }
  }

  // Pairs sharing bytes within a heap.
  std::vector<std::vector<uint32_t>> members(plan_.heaps.size());
  for (uint32_t r = 0; r < nr; ++r) {
    const Placement& pl = plan_.placements[r];
    if (life_[r].first == kNone || g_.resources[r].desc.persistent) continue;
    if (pl.heap != kNone && pl.heap < plan_.heaps.size()) members[pl.heap].push_back(r);
  }
  for (size_t h = 0; h < members.size(); ++h) {
    auto& m = members[h];
    std::sort(m.begin(), m.end(), [&](uint32_t a, uint32_t b) {
      return plan_.placements[a].offset < plan_.placements[b].offset;
    });
    std::vector<uint32_t> active;
    for (uint32_t r : m) {
      const uint64_t begin = plan_.placements[r].offset;
      active.erase(std::remove_if(active.begin(), active.end(),
                                  [&](uint32_t q) { return plan_.placements[q].offset + reqs_[q].size <= begin; }),
                   active.end());
      if (reqs_[r].size == 0) continue;
      for (uint32_t q : active) {
        const Lifetime& a = life_[q];
        const Lifetime& b = life_[r];
        if (!opt_.alias) {
          fail("alias", rn(q) + " and " + rn(r) + " share bytes in heap " + std::to_string(h) +
                            " although aliasing is off");
        }
        if (a.last < b.first) {
          alias_pairs_.emplace_back(q, r);
        } else if (b.last < a.first) {
          alias_pairs_.emplace_back(r, q);
        } else {
          fail("alias", rn(q) + " and " + rn(r) + " share bytes in heap " + std::to_string(h) +
                            " while both are alive (lifetimes overlap)");
        }
      }
      active.push_back(r);
    }
  }

  // Statistics.
  uint64_t lower = 0;
  for (auto& [cls, d] : diff) {
    int64_t cur = 0, best = 0;
    for (int64_t x : d) {
      cur += x;
      best = std::max(best, cur);
    }
    lower += static_cast<uint64_t>(best);
  }
  uint64_t heap_sum = 0;
  for (const Heap& h : plan_.heaps) heap_sum += h.size;
  const MemoryStats& ms = plan_.memory;
  if (ms.aliased_bytes != heap_sum) {
    fail("memory-stats", "aliased_bytes " + std::to_string(ms.aliased_bytes) + " is not the sum of heap sizes " +
                             std::to_string(heap_sum));
  }
  if (ms.lower_bound_bytes != lower) {
    fail("memory-stats", "lower_bound_bytes " + std::to_string(ms.lower_bound_bytes) + ", expected " +
                             std::to_string(lower));
  }
  if (!(ms.lower_bound_bytes <= ms.aliased_bytes && ms.aliased_bytes <= ms.unaliased_bytes)) {
    fail("memory-stats", "expected lower_bound <= aliased <= unaliased, got " + std::to_string(ms.lower_bound_bytes) +
                             " / " + std::to_string(ms.aliased_bytes) + " / " + std::to_string(ms.unaliased_bytes));
  }
  // Unaliased is what the side-by-side (--no-alias) layout allocates: at least the sum of
  // the sizes, more only by alignment padding (less than one alignment per resource).
  if (ms.unaliased_bytes < unaliased) {
    fail("memory-stats", "unaliased_bytes " + std::to_string(ms.unaliased_bytes) +
                             " is below the sum of used transient sizes " + std::to_string(unaliased));
  }
  if (!opt_.alias && ms.aliased_bytes != ms.unaliased_bytes) {
    fail("memory-stats", "with aliasing off, aliased_bytes " + std::to_string(ms.aliased_bytes) +
                             " differs from unaliased_bytes " + std::to_string(ms.unaliased_bytes));
  }
  if (ms.persistent_bytes != persistent) {
    fail("memory-stats", "persistent_bytes " + std::to_string(ms.persistent_bytes) +
                             ", expected the sum of used persistent sizes " + std::to_string(persistent));
  }
  if (ms.transient_count != transient_count) {
    fail("memory-stats", "transient_count " + std::to_string(ms.transient_count) + ", expected " +
                             std::to_string(transient_count) + " used transient resources");
  }
}

void Checker::check_handovers() {
  const size_t nr = g_.resources.size();
  handed_from_.assign(nr, {});
  auto overlap = [&](uint32_t a, uint32_t b) {
    const Placement& pa = plan_.placements[a];
    const Placement& pb = plan_.placements[b];
    if (pa.heap == kNone || pa.heap != pb.heap) return false;
    return pa.offset < pb.offset + reqs_[b].size && pb.offset < pa.offset + reqs_[a].size;
  };
  for (const Handover& h : plan_.handovers) {
    if (h.resource >= nr || h.previous >= nr) {
      fail("handover", "a handover names a resource out of range");
      continue;
    }
    const std::string what = "handover " + rn(h.previous) + " -> " + rn(h.resource);
    if (life_[h.resource].first == kNone || life_[h.previous].first == kNone) {
      fail("handover", what + " involves a resource without a live use");
      continue;
    }
    if (!overlap(h.resource, h.previous)) fail("handover", what + ": the two do not share bytes in one heap");
    if (!(life_[h.previous].last < life_[h.resource].first)) {
      fail("handover", what + ": the previous occupant is still alive when the new one starts");
    }
    handed_from_[h.resource].push_back(h.previous);
  }
  // Every earlier occupant of shared bytes must be reachable through hand-overs.
  std::vector<uint32_t> stamp(nr, 0);
  uint32_t tick = 0;
  std::vector<uint32_t> stack;
  std::sort(alias_pairs_.begin(), alias_pairs_.end(),
            [](const auto& a, const auto& b) { return a.second < b.second; });
  uint32_t current = kNone;
  for (const auto& [p, r] : alias_pairs_) {
    if (r != current) {
      current = r;
      ++tick;
      stack.assign(handed_from_[r].begin(), handed_from_[r].end());
      while (!stack.empty()) {
        const uint32_t q = stack.back();
        stack.pop_back();
        if (stamp[q] == tick) continue;
        stamp[q] = tick;
        for (uint32_t x : handed_from_[q]) stack.push_back(x);
      }
    }
    if (stamp[p] != tick) {
      fail("handover", rn(r) + " takes over bytes of " + rn(p) + " but no chain of handovers leads back to it");
    }
  }
  // The aliasing barrier before each new occupant's first use.
  for (uint32_t r = 0; r < nr; ++r) {
    if (handed_from_[r].empty()) continue;
    const uint32_t pos = life_[r].first;
    const PlannedPass& pp = plan_.order[pos];
    const Barrier* found = nullptr;
    for (uint32_t k = pp.barrier_begin; k < pp.barrier_begin + pp.barrier_count; ++k) {
      const Barrier& b = plan_.barriers[k];
      if (b.resource == r && b.aliasing) found = &b;
    }
    if (!found) {
      fail("handover", rn(r) + " is handed over but has no aliasing barrier before its first use at " + at(pos));
      continue;
    }
    if (is_image(r) && found->from.layout != Layout::undefined) {
      fail("handover", "aliasing barrier of " + rn(r) + " before " + at(pos) + " has old layout " +
                           std::string(layout_name(found->from.layout)) + ", expected undefined");
    }
    // The new occupant's first use must wait on this barrier (for buffers nothing else
    // orders it after the previous occupant).
    if (const PassUse* first = use_of(pos, r)) {
      if (!covers(expand_dst(found->to.stages), norm_stages(first->state.stages)) ||
          !covers(norm_access(found->to.access), first->reads | first->writes)) {
        fail("handover", "aliasing barrier " + barrier_text(*found) + " of " + rn(r) + " before " + at(pos) +
                             " does not reach its first use " + state_text(first->state));
      }
    }
    for (uint32_t q : handed_from_[r]) {
      if (life_[q].first == kNone || life_[q].last >= plan_.order.size()) continue;
      const PassUse* u = use_of(life_[q].last, q);
      if (!u) continue;
      if (!covers(expand_src(found->from.stages), norm_stages(u->state.stages))) {
        fail("handover", "aliasing barrier of " + rn(r) + " before " + at(pos) + " waits for " +
                             stage_names(found->from.stages) + " but the previous occupant " + rn(q) +
                             " was last used at " + stage_names(u->state.stages) + " by " + at(life_[q].last));
      }
      if (u->writes && !covers(norm_access(found->from.access), u->writes)) {
        fail("handover", "aliasing barrier of " + rn(r) + " before " + at(pos) + " does not cover the write " +
                             access_names(u->writes) + " of the previous occupant " + rn(q) + " by " +
                             at(life_[q].last) + " (write after write on shared memory)");
      }
    }
  }
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const PlannedPass& pp = plan_.order[pos];
    for (uint32_t k = pp.barrier_begin; k < pp.barrier_begin + pp.barrier_count; ++k) {
      const Barrier& b = plan_.barriers[k];
      if (!b.aliasing) continue;
      if (b.resource == kNone) {
        fail("handover", "a global barrier before " + at(pos) + " is marked aliasing");
      } else if (handed_from_[b.resource].empty()) {
        fail("handover", "aliasing barrier for " + rn(b.resource) + " before " + at(pos) +
                             " but no handover names it");
      } else if (life_[b.resource].first != pos) {
        fail("handover", "aliasing barrier for " + rn(b.resource) + " before " + at(pos) +
                             " is not at its first use");
      }
    }
  }
}

// ---------------------------------------------------------------------------------------
// Barrier replay.

void Checker::apply_barrier(uint32_t r, RState& st, const Barrier& b, uint32_t pos, bool report,
                            const std::string& tag) {
  const bool image = r == kNone ? false : is_image(r);
  const bool global = b.resource == kNone;
  const uint32_t fs = expand_src(b.from.stages);
  const uint32_t fn = norm_stages(b.from.stages);
  const uint32_t fa = norm_access(b.from.access);
  const uint32_t tx = expand_dst(b.to.stages);
  const uint32_t tn = norm_stages(b.to.stages);
  const uint32_t ta = norm_access(b.to.access);
  auto where = [&] { return "barrier " + barrier_text(b) + " for " + rn(r) + " before " + at(pos) + tag; };

  const bool transition = !global && image && b.from.layout != b.to.layout;
  if (!global && report) {
    if (!image && (b.from.layout != Layout::none || b.to.layout != Layout::none)) {
      fail("barrier", where() + ": buffers have no layout (expected none -> none)");
    }
    if (image && (b.from.layout == Layout::none || b.to.layout == Layout::none)) {
      fail("barrier", where() + ": images need a layout, not none");
    }
    if (image && !transition && b.from.layout != st.layout) {
      fail("barrier", where() + ": the resource is in layout " + std::string(layout_name(st.layout)));
    }
  }

  if (transition) {
    if (report) {
      if (b.from.layout != st.layout && b.from.layout != Layout::undefined) {
        fail("barrier", where() + ": old layout does not match the current layout " +
                            std::string(layout_name(st.layout)) + " (and is not undefined)");
      }
      for (uint32_t s = 0; s < kStageCount; ++s) {
        if (!(st.read_stages & (1u << s))) continue;
        if (!((fs & (1u << s)) || (st.read_before[s] & fs))) {
          fail("barrier", where() + ": the layout transition does not wait for the earlier read at " +
                              stage_names(1u << s) + " (write after read)");
        }
      }
      if (st.written) {
        const bool exec = (st.w_stages != 0 && covers(fs, st.w_stages)) || (st.w_before & fs);
        const bool avail = st.w_available || (st.w_stages != 0 && covers(fn, st.w_stages) && covers(fa, st.w_access));
        if (!exec || !avail) {
          fail("barrier", where() + ": the layout transition does not wait for the last write (" +
                              stage_names(st.w_stages) + "/" + access_names(st.w_access) + ")");
        }
      }
    }
    if (b.from.layout == Layout::undefined) st.content_valid = false;
    st.layout = b.to.layout;
    st.written = true;
    st.w_stages = tn;
    st.w_access = 0;
    st.w_available = true;
    st.w_before = tx;
    st.vis.fill(0);
    for (uint32_t s = 0; s < kStageCount; ++s) {
      if (tn & (1u << s)) st.vis[s] = ta;
    }
    st.read_stages = 0;
    st.read_before.fill(0);
    st.accessed = true;
    return;
  }

  // No layout change: order earlier accesses in the first scope before the second.
  for (uint32_t s = 0; s < kStageCount; ++s) {
    if (!(st.read_stages & (1u << s))) continue;
    if ((fs & (1u << s)) || (st.read_before[s] & fs)) st.read_before[s] |= tx;
  }
  if (st.written) {
    const bool direct = st.w_stages != 0 && covers(fs, st.w_stages);
    const bool chained = (st.w_before & fs) != 0;
    if (direct || chained) {
      if (st.w_stages != 0 && covers(fn, st.w_stages) && covers(fa, st.w_access)) st.w_available = true;
      st.w_before |= tx;
      if (st.w_available) {
        for (uint32_t s = 0; s < kStageCount; ++s) {
          if (tn & (1u << s)) st.vis[s] |= ta;
        }
      }
    }
  }
  if (!global) st.accessed = true;
}

void Checker::apply_use(uint32_t r, RState& st, const PassUse& u, uint32_t pos, bool report, const std::string& tag) {
  const uint32_t s_use = norm_stages(u.state.stages);
  auto where = [&] {
    return at(pos) + " uses " + rn(r) + " as " + state_text(u.state) + tag;
  };
  if (report) {
    if (st.layout != u.state.layout) {
      fail("layout", where() + " but it is in layout " + std::string(layout_name(st.layout)));
    }
    if (u.reads && st.written) {
      uint32_t missing = 0;
      for (uint32_t s = 0; s < kStageCount; ++s) {
        if ((s_use & (1u << s)) && !covers(st.vis[s], u.reads)) missing |= 1u << s;
      }
      if (missing) {
        fail("hazard", where() + ": the last write (" + stage_names(st.w_stages) + "/" + access_names(st.w_access) +
                           ") is not visible to its reads at " + stage_names(missing) + " (read after write)");
      }
    }
    if (u.reads && !st.content_valid && st.first_use_done) {
      fail("discard", where() + ": it reads contents that a transition from undefined discarded");
    }
    if (u.writes && st.written) {
      uint32_t missing = 0;
      for (uint32_t s = 0; s < kStageCount; ++s) {
        if ((s_use & (1u << s)) && !covers(st.vis[s], u.writes)) missing |= 1u << s;
      }
      if (missing) {
        fail("hazard", where() + ": the last write (" + stage_names(st.w_stages) + "/" + access_names(st.w_access) +
                           ") is not ordered and visible before its write at " + stage_names(missing) +
                           " (write after write)");
      }
    }
    if (u.writes) {
      for (uint32_t s = 0; s < kStageCount; ++s) {
        if (!(st.read_stages & (1u << s))) continue;
        if (!covers(st.read_before[s], s_use)) {
          fail("hazard", where() + ": an earlier read at " + stage_names(1u << s) +
                             " is not ordered before this write (write after read)");
        }
      }
    }
  }
  if (u.writes) {
    st.written = true;
    st.w_stages = s_use;
    st.w_access = u.writes;
    st.w_available = false;
    st.w_before = 0;
    st.vis.fill(0);
    st.read_stages = 0;
    st.read_before.fill(0);
    st.content_valid = true;
  } else {
    for (uint32_t s = 0; s < kStageCount; ++s) {
      if (!(s_use & (1u << s))) continue;
      st.read_stages |= 1u << s;
      st.read_before[s] = 0;
    }
  }
  st.accessed = true;
  st.have_last_use = true;
  st.last_use_read_only = u.writes == 0;
  st.last_use_layout = u.state.layout;
  st.first_use_done = true;
}

void Checker::check_barriers() {
  const uint32_t n = static_cast<uint32_t>(plan_.order.size());
  const size_t nr = g_.resources.size();
  std::vector<std::vector<Event>>& events = events_;
  std::vector<GlobalBarrier>& globals = globals_;
  events.assign(nr, {});
  globals.clear();
  for (uint32_t pos = 0; pos < n; ++pos) {
    const PlannedPass& pp = plan_.order[pos];
    uint32_t global_count = 0;
    for (uint32_t k = pp.barrier_begin; k < pp.barrier_begin + pp.barrier_count; ++k) {
      const Barrier& b = plan_.barriers[k];
      if (b.resource == kNone) {
        ++global_count;
        globals.push_back({pos, k});
        if (!opt_.serialize) fail("barrier", "a global barrier before " + at(pos) + " although serialize is off");
        const bool full = norm_stages(b.from.stages) == kRealStages && norm_stages(b.to.stages) == kRealStages &&
                          covers(norm_access(b.from.access), kWriteBits) &&
                          covers(norm_access(b.to.access), kReadBits | kWriteBits);
        if (opt_.serialize && !full) {
          fail("serialize", "the global barrier " + barrier_text(b) + " before " + at(pos) + " is not a full barrier");
        }
      } else {
        events[b.resource].push_back({pos, false, k});
      }
    }
    if (opt_.serialize && pos > 0 && global_count == 0) {
      fail("serialize", "no global barrier before " + at(pos));
    }
    if (global_count > 1) fail("barrier", std::to_string(global_count) + " global barriers before " + at(pos));
    for (uint32_t i = 0; i < uses_at_[pos].size(); ++i) events[uses_at_[pos][i].resource].push_back({pos, true, i});
  }
  global_run_end_.assign(globals.size(), globals.size());
  for (size_t i = globals.size(); i-- > 0;) {
    if (i + 1 < globals.size()) {
      const Barrier& a = plan_.barriers[globals[i].index];
      const Barrier& b = plan_.barriers[globals[i + 1].index];
      const bool same = a.from == b.from && a.to == b.to && a.aliasing == b.aliasing;
      global_run_end_[i] = same ? global_run_end_[i + 1] : i + 1;
    }
  }
  // Within a pass the resource's own barriers come first (std::stable_sort keeps the
  // recorded order of barriers), then the use.
  for (auto& ev : events) {
    std::stable_sort(ev.begin(), ev.end(), [](const Event& a, const Event& b) {
      if (a.pos != b.pos) return a.pos < b.pos;
      return !a.is_use && b.is_use;
    });
  }

  for (uint32_t r = 0; r < nr; ++r) {
    // Barriers for resources the pass does not use, and duplicates.
    const auto& ev = events[r];
    for (size_t i = 0; i < ev.size(); ++i) {
      if (ev[i].is_use) continue;
      if (!use_of(ev[i].pos, r)) {
        fail("minimal", "barrier " + barrier_text(plan_.barriers[ev[i].index]) + " for " + rn(r) + " before " +
                            at(ev[i].pos) + ", which does not use it");
      }
      if (i > 0 && !ev[i - 1].is_use && ev[i - 1].pos == ev[i].pos) {
        fail("minimal", "more than one barrier for " + rn(r) + " before " + at(ev[i].pos));
      }
    }
    if (life_[r].first == kNone) continue;
    if (g_.resources[r].desc.persistent) {
      replay_frames(r);
    } else {
      RState st;
      st.layout = is_image(r) ? Layout::undefined : Layout::none;
      replay(r, st, true, "");
    }
  }
  for (const Barrier& b : plan_.initial_barriers) {
    if (b.resource >= nr || !g_.resources[b.resource].desc.persistent || !is_image(b.resource) || life_[b.resource].first == kNone) {
      fail("initial", "initial barrier " + barrier_text(b) + " for " + rn(b.resource) + ", which is not a used persistent texture");
    }
  }
}

// A persistent resource's object over the first frames: put in place once by the plan's
// initial barrier, then each frame's uses and barriers — a history pair's object takes
// the output's role and its history's by turns (the executor swaps them every frame), so
// two frames make its period; four cover the first frame and the steady state.
void Checker::replay_frames(uint32_t r) {
  const GraphResource& res = g_.resources[r];
  const uint32_t partner = res.previous != kNone ? res.previous : res.previous_of;
  const bool paired = partner != kNone && life_[partner].first != kNone;
  RState st;
  st.layout = is_image(r) ? Layout::undefined : Layout::none;
  std::vector<const Barrier*> initial;
  for (const Barrier& b : plan_.initial_barriers) {
    if (b.resource == r) initial.push_back(&b);
  }
  if (initial.size() != (is_image(r) ? 1u : 0u)) {
    fail("initial", rn(r) + " has " + std::to_string(initial.size()) + " initial barriers, expected " +
                        (is_image(r) ? "one (a persistent texture)" : "none (a buffer)"));
  }
  if (!initial.empty()) apply_barrier(r, st, *initial[0], 0, true, " [before the first frame]");
  // The plan's barriers serve the steady state: in the first frame one may find nothing
  // to wait on. Contents carried over are the last frame's (a history the pass does not
  // read on the first frame; an output made anew).
  st.accessed = true;
  for (int frame = 0; frame < 4; ++frame) {
    if (frame > 0) st.content_valid = true;
    const uint32_t role = paired && frame % 2 == 1 ? partner : r;
    std::string tag = " [persistent, frame " + std::to_string(frame);
    if (paired) tag += ", the object of " + rn(r) + " as " + rn(role);
    replay(role, st, true, tag + "]");
  }
}

void Checker::replay(uint32_t r, RState& st, bool report, const std::string& tag) {
  size_t gi = 0;
  // Global barriers up to a position. Applying one barrier twice with nothing in between
  // changes nothing, so a run of identical global barriers counts once (this keeps the
  // --serialize replay linear).
  auto apply_globals = [&](uint32_t until_pos, bool inclusive) {
    const auto end_it = std::partition_point(globals_.begin() + static_cast<std::ptrdiff_t>(gi), globals_.end(),
                                             [&](const GlobalBarrier& x) {
                                               return x.pos < until_pos || (inclusive && x.pos == until_pos);
                                             });
    const size_t end = static_cast<size_t>(end_it - globals_.begin());
    while (gi < end) {
      apply_barrier(r, st, plan_.barriers[globals_[gi].index], globals_[gi].pos, false, tag);
      gi = std::min(end, global_run_end_[gi]);
    }
  };
  for (const Event& e : events_[r]) {
    if (!e.is_use) {
      apply_globals(e.pos, false);
      const Barrier& b = plan_.barriers[e.index];
      if (report) {
        const PassUse* u = use_of(e.pos, r);
        if (u && !b.aliasing && u->writes == 0 && st.have_last_use && st.last_use_read_only &&
            st.layout == u->state.layout && st.last_use_layout == u->state.layout) {
          bool visible = true;
          const uint32_t s_use = norm_stages(u->state.stages);
          for (uint32_t s = 0; s < kStageCount; ++s) {
            if ((s_use & (1u << s)) && st.written && !covers(st.vis[s], u->reads)) visible = false;
          }
          if (visible) {
            fail("minimal", "unneeded barrier " + barrier_text(b) + " for " + rn(r) + " before " + at(e.pos) +
                                ": the previous use was a read in the same layout and the last write is "
                                "already visible to " + state_text(u->state) + tag);
          }
        }
        if (!st.accessed && !b.aliasing && b.from.layout == b.to.layout) {
          fail("minimal", "unneeded barrier " + barrier_text(b) + " for " + rn(r) + " before " + at(e.pos) +
                              ": nothing touched the resource before and the layout does not change" + tag);
        }
      }
      apply_barrier(r, st, b, e.pos, report, tag);
    } else {
      apply_globals(e.pos, true);
      apply_use(r, st, uses_at_[e.pos][e.index], e.pos, report, tag);
    }
  }
  apply_globals(static_cast<uint32_t>(plan_.order.size()), true);
}

}  // namespace

std::vector<std::string> check_plan(const Graph& graph, const Plan& plan, const CompileOptions& options) {
  return check_plan(graph, plan, options, RequirementsFn{});
}

std::vector<std::string> check_plan(const Graph& graph, const Plan& plan, const CompileOptions& options,
                                    const RequirementsFn& requirements) {
  Checker c(graph, plan, options, requirements);
  return c.run();
}

ExpectedCulling expected_culling(const Graph& graph, bool cull) {
  Plan dummy;
  CompileOptions options;
  options.cull = cull;
  Checker c(graph, dummy, options, RequirementsFn{});
  ExpectedCulling e;
  if (!c.model_culling()) return e;
  e.live = c.live_;
  e.reason = c.reason_;
  return e;
}

std::string plan_text(const Graph& graph, const Plan& plan) {
  std::ostringstream os;
  auto state = [](const AccessState& s) {
    return stage_names(s.stages) + "/" + access_names(s.access) + "/" + std::string(layout_name(s.layout));
  };
  auto rname = [&](uint32_t r) {
    if (r == kNone) return std::string("<global>");
    if (r >= graph.resources.size()) return "#" + std::to_string(r);
    return graph.resources[r].desc.name + "(#" + std::to_string(r) + ")";
  };
  os << "plan: " << plan.order.size() << " passes run, " << plan.culled.size() << " culled\n";
  for (size_t i = 0; i < plan.order.size(); ++i) {
    const PlannedPass& pp = plan.order[i];
    for (uint32_t k = pp.barrier_begin; k < pp.barrier_begin + pp.barrier_count && k < plan.barriers.size(); ++k) {
      const Barrier& b = plan.barriers[k];
      os << "      barrier " << rname(b.resource) << " " << state(b.from) << " -> " << state(b.to)
         << (b.aliasing ? " aliasing" : "") << "\n";
    }
    os << "  " << i << ": "
       << (pp.pass < graph.passes.size() ? graph.passes[pp.pass].name : std::string("?")) << " (#" << pp.pass << ")\n";
  }
  for (const CulledPass& c : plan.culled) {
    os << "  culled " << (c.pass < graph.passes.size() ? graph.passes[c.pass].name : std::string("?")) << " (#"
       << c.pass << "): " << cull_reason_name(c.reason) << " "
       << (c.pass < graph.passes.size() && c.slot < graph.passes[c.pass].decl->slots.size() ? cull_detail(graph, c) : "?")
       << "\n";
  }
  for (size_t r = 0; r < plan.lifetimes.size() && r < plan.placements.size(); ++r) {
    const Lifetime& l = plan.lifetimes[r];
    const Placement& p = plan.placements[r];
    os << "  " << rname(static_cast<uint32_t>(r)) << " life ["
       << (l.first == kNone ? std::string("-") : std::to_string(l.first)) << ", "
       << (l.last == kNone ? std::string("-") : std::to_string(l.last)) << "] heap "
       << (p.heap == kNone ? std::string("-") : std::to_string(p.heap)) << " @" << p.offset << " +"
       << p.requirements.size << "\n";
  }
  for (size_t h = 0; h < plan.heaps.size(); ++h) {
    os << "  heap " << h << " class " << plan.heaps[h].heap_class << " size " << plan.heaps[h].size << "\n";
  }
  for (const Handover& h : plan.handovers) os << "  handover " << rname(h.previous) << " -> " << rname(h.resource) << "\n";
  os << "  memory: aliased " << plan.memory.aliased_bytes << " unaliased " << plan.memory.unaliased_bytes
     << " lower " << plan.memory.lower_bound_bytes << " persistent " << plan.memory.persistent_bytes << " transient "
     << plan.memory.transient_count << "\n";
  return os.str();
}

namespace {

bool same_description(const ResourceDesc& a, const ResourceDesc& b) {
  return a.kind == b.kind && a.format == b.format && a.extent.width == b.extent.width &&
         a.extent.height == b.extent.height && a.extent.depth == b.extent.depth &&
         (a.kind != ResourceKind::buffer || a.buffer_bytes == b.buffer_bytes);
}

bool overlap(const Lifetime& a, const Lifetime& b) { return a.first <= b.last && b.first <= a.last; }

}  // namespace

std::vector<std::string> check_pool(const Graph& graph, const Plan& plan, const ResourcePool& pool) {
  std::vector<std::string> v;
  auto name = [&](uint32_t r) { return graph.resources[r].desc.name; };
  std::vector<int> seen(graph.resources.size(), 0);
  uint64_t transient = 0, persistent = 0;
  for (uint32_t o = 0; o < pool.objects.size(); ++o) {
    const PooledObject& object = pool.objects[o];
    (object.persistent ? persistent : transient) += object.bytes;
    if ((object.persistent || !plan.options.alias) && object.occupants.size() != 1) {
      v.push_back("pool: object " + std::to_string(o) + " must hold one resource, holds " + std::to_string(object.occupants.size()));
    }
    for (size_t i = 0; i < object.occupants.size(); ++i) {
      const uint32_t r = object.occupants[i];
      ++seen[r];
      if (pool.object_of[r] != o) v.push_back("pool: " + name(r) + " is in object " + std::to_string(o) + " but object_of says otherwise");
      if (!same_description(graph.resources[r].desc, object.desc)) v.push_back("pool: " + name(r) + " differs from object " + std::to_string(o));
      for (size_t j = 0; j < i; ++j) {
        const uint32_t q = object.occupants[j];
        if (overlap(plan.lifetimes[q], plan.lifetimes[r])) v.push_back("pool: " + name(q) + " and " + name(r) + " share an object while both are alive");
      }
    }
  }
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {
    const bool live = plan.lifetimes[r].first != kNone;
    if (live && seen[r] != 1) v.push_back("pool: " + name(r) + " is in " + std::to_string(seen[r]) + " objects");
    if (!live && (seen[r] != 0 || pool.object_of[r] != kNone)) v.push_back("pool: unused " + name(r) + " has an object");
  }
  if (transient != pool.transient_bytes) v.push_back("pool: transient_bytes is not the sum of the transient objects");
  if (persistent != pool.persistent_bytes) v.push_back("pool: persistent_bytes is not the sum of the persistent objects");
  return v;
}

}  // namespace volgraph::test
