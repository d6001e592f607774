// The checker must not be vacuous: breaking a correct plan in any one way must be caught.
// Also a strong minimality property: in a plan the checker accepts, every barrier is
// needed, so removing any single barrier must produce a violation.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/property/property_common.h"

namespace volgraph::test {
namespace {

Plan without_barrier(const Plan& p, uint32_t k) {
  Plan q = p;
  q.barriers.erase(q.barriers.begin() + k);
  for (PlannedPass& pp : q.order) {
    if (pp.barrier_begin > k) {
      --pp.barrier_begin;
    } else if (k < pp.barrier_begin + pp.barrier_count) {
      --pp.barrier_count;
    }
  }
  return q;
}

Plan with_barrier(const Plan& p, uint32_t pos, const Barrier& b) {
  Plan q = p;
  const uint32_t at = q.order[pos].barrier_begin + q.order[pos].barrier_count;
  q.barriers.insert(q.barriers.begin() + at, b);
  ++q.order[pos].barrier_count;
  for (uint32_t i = 0; i < q.order.size(); ++i) {
    if (i != pos && q.order[i].barrier_begin >= at) ++q.order[i].barrier_begin;
  }
  return q;
}

struct Case {
  uint64_t seed;
  RandomGraphOptions o;
  RandomGraph g;
  CompileOptions options;
  Plan plan;
};

// Plans the checker accepts, to mutate.
std::vector<Case> clean_cases(uint64_t first, uint64_t count, const CompileOptions& options) {
  std::vector<Case> out;
  for (uint64_t seed = first; seed < first + count; ++seed) {
    Case c;
    c.seed = seed;
    c.o = options_for_seed(seed, 80);
    c.g = make_random_graph(c.o);
    c.options = options;
    c.plan = compile(c.g.graph, options);
    if (check_plan(c.g.graph, c.plan, options).empty()) out.push_back(std::move(c));
  }
  return out;
}

TEST(CheckerSelfTest, RemovingAnyBarrierIsCaught) {
  for (const Combo& combo : {combos()[0], combos()[3]}) {
    const auto cases = clean_cases(1, 60, combo.options);
    ASSERT_GT(cases.size(), 10u) << "too few clean plans to mutate (" << combo.name << ")";
    int misses = 0;
    size_t tried = 0;
    for (const Case& c : cases) {
      for (uint32_t k = 0; k < c.plan.barriers.size() && k < 300; ++k) {
        const Barrier& candidate = c.plan.barriers[k];
        // Under --serialize the full barrier before each pass already orders everything,
        // so only layout transitions and the global barriers themselves are indispensable.
        if (c.options.serialize && candidate.resource != kNone && candidate.from.layout == candidate.to.layout) {
          continue;
        }
        ++tried;
        const Plan broken = without_barrier(c.plan, k);
        if (!check_plan(c.g.graph, broken, c.options).empty()) continue;
        const Barrier& b = c.plan.barriers[k];
        ADD_FAILURE() << describe(c.seed, c.o, combo.name) << "\nremoving barrier " << k << " ("
                      << (b.resource == kNone ? std::string("global") : c.g.graph.resources[b.resource].desc.name)
                      << " " << stage_names(b.from.stages) << "/" << access_names(b.from.access) << "/"
                      << layout_name(b.from.layout) << " -> " << stage_names(b.to.stages) << "/"
                      << access_names(b.to.access) << "/" << layout_name(b.to.layout)
                      << ") goes unnoticed: the barrier is not needed, or the checker misses a hazard";
        if (++misses >= 5) return;
      }
    }
    EXPECT_GT(tried, 100u);
  }
}

TEST(CheckerSelfTest, AddingAReadAfterReadBarrierIsCaught) {
  const auto cases = clean_cases(100, 40, CompileOptions{});
  int tried = 0;
  for (const Case& c : cases) {
    for (uint32_t pos = 0; pos < c.plan.order.size(); ++pos) {
      const GraphPass& pass = c.g.graph.passes[c.plan.order[pos].pass];
      for (const ResourceUse& u : pass.uses) {
        if (u.direction != SlotDirection::input || usage_writes(u.usage)) continue;
        if (pass.uses.size() > 1 && std::count_if(pass.uses.begin(), pass.uses.end(), [&](const ResourceUse& x) {
                                        return x.resource == u.resource;
                                      }) > 1) {
          continue;
        }
        if (c.plan.lifetimes[u.resource].first == kNone || c.plan.lifetimes[u.resource].first == pos) continue;
        bool has = false;
        const PlannedPass& pp = c.plan.order[pos];
        for (uint32_t k = pp.barrier_begin; k < pp.barrier_begin + pp.barrier_count; ++k) {
          has = has || c.plan.barriers[k].resource == u.resource;
        }
        if (has) continue;
        Barrier b;
        b.resource = u.resource;
        b.from = b.to = access_state(u.usage, pass.kind, c.g.graph.resources[u.resource].desc.kind);
        ++tried;
        EXPECT_FALSE(check_plan(c.g.graph, with_barrier(c.plan, pos, b), c.options).empty())
            << describe(c.seed, c.o, "default") << "\nan extra read-after-read barrier before position " << pos
            << " was not reported";
      }
    }
  }
  EXPECT_GT(tried, 20);
}

// Whether the pass that used barrier k's resource last before it wrote it.
bool previous_use_writes(const Case& c, uint32_t k) {
  const uint32_t r = c.plan.barriers[k].resource;
  uint32_t pos = kNone;
  for (uint32_t i = 0; i < c.plan.order.size(); ++i) {
    const PlannedPass& pp = c.plan.order[i];
    if (k >= pp.barrier_begin && k < pp.barrier_begin + pp.barrier_count) pos = i;
  }
  for (uint32_t i = pos; i-- > 0;) {
    bool used = false, writes = false;
    for (const ResourceUse& u : c.g.graph.passes[c.plan.order[i].pass].uses) {
      if (u.resource != r) continue;
      used = true;
      writes = writes || usage_writes(u.usage);
    }
    if (used) return writes;
  }
  return false;
}

TEST(CheckerSelfTest, CorruptingABarrierIsCaught) {
  const auto cases = clean_cases(300, 60, CompileOptions{});
  int misses = 0;
  size_t tried = 0;
  auto report = [&](const Case& c, uint32_t k, const char* what) {
    const Barrier& b = c.plan.barriers[k];
    ADD_FAILURE() << describe(c.seed, c.o, "default") << "\n" << what << " of barrier " << k << " ("
                  << c.g.graph.resources[b.resource].desc.name << " " << stage_names(b.from.stages) << "/"
                  << access_names(b.from.access) << "/" << layout_name(b.from.layout) << " -> "
                  << stage_names(b.to.stages) << "/" << access_names(b.to.access) << "/" << layout_name(b.to.layout)
                  << (b.aliasing ? " aliasing" : "") << ") goes unnoticed";
    return ++misses < 5;
  };
  for (const Case& c : cases) {
    for (uint32_t k = 0; k < c.plan.barriers.size() && k < 200; ++k) {
      const Barrier& b = c.plan.barriers[k];
      if (b.resource == kNone) continue;
      // Wait for / make visible to the wrong stage.
      {
        Plan broken = c.plan;
        broken.barriers[k].to.stages = (b.to.stages & stage::copy) ? stage::compute_shader : stage::copy;
        ++tried;
        if (check_plan(c.g.graph, broken, c.options).empty() && !report(c, k, "changing to.stages")) return;
      }
      // Forget the write it must make available (when that write is the resource's
      // previous use; later barriers may rely on an earlier one's availability).
      if ((b.from.access & access::all_writes) && previous_use_writes(c, k)) {
        Plan broken = c.plan;
        broken.barriers[k].from.access = access::none;
        ++tried;
        if (check_plan(c.g.graph, broken, c.options).empty() && !report(c, k, "clearing from.access")) return;
      }
      // Wait for nothing.
      if (b.from.stages != stage::none) {
        Plan broken = c.plan;
        broken.barriers[k].from.stages = stage::none;
        broken.barriers[k].from.access = access::none;
        ++tried;
        if (check_plan(c.g.graph, broken, c.options).empty() && !report(c, k, "clearing from.stages")) return;
      }
      // Claim a wrong old layout (neither the current one nor undefined).
      if (b.from.layout != b.to.layout && b.from.layout != Layout::undefined) {
        Plan broken = c.plan;
        broken.barriers[k].from.layout = b.from.layout == Layout::transfer_src ? Layout::transfer_dst : Layout::transfer_src;
        ++tried;
        if (check_plan(c.g.graph, broken, c.options).empty() && !report(c, k, "a wrong from.layout")) return;
      }
      // Drop the aliasing flag.
      if (b.aliasing) {
        Plan broken = c.plan;
        broken.barriers[k].aliasing = false;
        ++tried;
        if (check_plan(c.g.graph, broken, c.options).empty() && !report(c, k, "dropping the aliasing flag")) return;
      }
    }
  }
  EXPECT_GT(tried, 500u);
}

TEST(CheckerSelfTest, BreakingOtherAspectsIsCaught) {
  const auto cases = clean_cases(200, 60, CompileOptions{});
  int swaps = 0, heaps = 0, handovers = 0, culls = 0, lifetimes = 0, overlaps = 0;
  for (const Case& c : cases) {
    const Graph& g = c.g.graph;
    auto expect_caught = [&](const Plan& broken, const char* what) {
      EXPECT_FALSE(check_plan(g, broken, c.options).empty()) << describe(c.seed, c.o, "default") << "\n" << what
                                                             << " was not reported";
    };
    // Swap a pass with the one before it when it reads what that one made.
    for (uint32_t i = 0; i + 1 < c.plan.order.size(); ++i) {
      const uint32_t a = c.plan.order[i].pass, b = c.plan.order[i + 1].pass;
      bool depends = false;
      for (const ResourceUse& u : g.passes[b].uses) {
        depends = depends || (u.direction != SlotDirection::output && g.resources[u.resource].version_writers[u.version] == a);
      }
      if (!depends) continue;
      Plan broken = c.plan;
      std::swap(broken.order[i], broken.order[i + 1]);
      broken.position[a] = i + 1;
      broken.position[b] = i;
      expect_caught(broken, "running a pass before its producer");
      ++swaps;
      break;
    }
    // Shrink a heap that is used to its last byte.
    for (uint32_t h = 0; h < c.plan.heaps.size(); ++h) {
      uint64_t end = 0;
      for (uint32_t r = 0; r < g.resources.size(); ++r) {
        const Placement& p = c.plan.placements[r];
        if (p.heap == h && c.plan.lifetimes[r].first != kNone) end = std::max(end, p.offset + p.requirements.size);
      }
      if (end != c.plan.heaps[h].size || end == 0) continue;
      Plan broken = c.plan;
      broken.heaps[h].size -= 1;
      expect_caught(broken, "a heap one byte too small");
      ++heaps;
      break;
    }
    // Move a transient onto the bytes of another one alive at the same time.
    for (uint32_t a = 0; a < g.resources.size() && !c.plan.heaps.empty(); ++a) {
      const Placement& pa = c.plan.placements[a];
      if (pa.heap == kNone || c.plan.lifetimes[a].first == kNone) continue;
      bool moved = false;
      for (uint32_t b = 0; b < g.resources.size(); ++b) {
        const Placement& pb = c.plan.placements[b];
        if (b == a || pb.heap != pa.heap || c.plan.lifetimes[b].first == kNone) continue;
        const Lifetime& la = c.plan.lifetimes[a];
        const Lifetime& lb = c.plan.lifetimes[b];
        if (la.last < lb.first || lb.last < la.first) continue;
        if (pb.requirements.size > pa.requirements.size || pb.requirements.alignment != pa.requirements.alignment) continue;
        Plan broken = c.plan;
        broken.placements[b].offset = pa.offset;
        expect_caught(broken, "two live resources on the same bytes");
        ++overlaps;
        moved = true;
        break;
      }
      if (moved) break;
    }
    {
      Plan broken = c.plan;
      broken.memory.lower_bound_bytes += 1;
      expect_caught(broken, "a wrong lower bound");
    }
    // Drop every handover of one resource.
    if (!c.plan.handovers.empty()) {
      Plan broken = c.plan;
      const uint32_t r = broken.handovers[0].resource;
      std::erase_if(broken.handovers, [&](const Handover& x) { return x.resource == r; });
      expect_caught(broken, "dropping the handovers of a resource");
      ++handovers;
    }
    // Forget a culled pass, or claim a wrong reason.
    if (!c.plan.culled.empty()) {
      Plan broken = c.plan;
      broken.culled.pop_back();
      expect_caught(broken, "a culled pass missing from plan.culled");
      Plan wrong = c.plan;
      wrong.culled[0].reason = wrong.culled[0].reason == CullReason::unused ? CullReason::scene_lacks : CullReason::unused;
      expect_caught(wrong, "a wrong cull reason");
      ++culls;
    }
    // Stretch a lifetime.
    for (uint32_t r = 0; r < g.resources.size(); ++r) {
      if (c.plan.lifetimes[r].first == kNone || c.plan.lifetimes[r].first == 0) continue;
      Plan broken = c.plan;
      --broken.lifetimes[r].first;
      expect_caught(broken, "a lifetime starting too early");
      ++lifetimes;
      break;
    }
  }
  EXPECT_GT(swaps, 5);
  EXPECT_GT(heaps, 0);
  EXPECT_GT(handovers, 0);
  EXPECT_GT(culls, 5);
  EXPECT_GT(lifetimes, 5);
  EXPECT_GT(overlaps, 5);
}

// Pooling: moving a resource into the object of one alive at the same time, or into an
// object of another description, is caught; an untouched pool passes.
TEST(CheckerSelfTest, BreakingThePoolIsCaught) {
  int broken_overlap = 0, broken_description = 0;
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    const RandomGraph g = make_random_graph(options_for_seed(seed));
    const Plan plan = compile(g.graph);
    const ResourcePool pool = pool_resources(g.graph, plan);
    ASSERT_TRUE(check_pool(g.graph, plan, pool).empty()) << "seed " << seed;
    for (uint32_t a = 0; a < g.graph.resources.size(); ++a) {
      for (uint32_t b = a + 1; b < g.graph.resources.size(); ++b) {
        const uint32_t oa = pool.object_of[a], ob = pool.object_of[b];
        if (oa == kNone || ob == kNone || oa == ob || pool.objects[ob].occupants.size() != 1) continue;
        const Lifetime& la = plan.lifetimes[a];
        const Lifetime& lb = plan.lifetimes[b];
        const bool overlapping = la.first <= lb.last && lb.first <= la.last;
        ResourcePool broken = pool;  // b moves into a's object
        broken.objects[oa].occupants.push_back(b);
        broken.objects[ob].occupants.clear();
        broken.object_of[b] = oa;
        if (check_pool(g.graph, plan, broken).empty()) {
          EXPECT_FALSE(overlapping) << "seed " << seed << ": overlap not caught";
          continue;
        }
        broken_overlap += overlapping ? 1 : 0;
        broken_description += overlapping ? 0 : 1;
      }
    }
  }
  EXPECT_GT(broken_overlap, 10);
  EXPECT_GT(broken_description, 10);
}

}  // namespace
}  // namespace volgraph::test
