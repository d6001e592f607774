// Shared helpers of the property tests: which graphs a seed gives, the option
// combinations, a second requirements function, and plan comparison.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "graph/plan.h"
#include "tests/support/plan_checker.h"
#include "tests/support/random_graph.h"

namespace volgraph {
// Readable values in gtest messages.
inline void PrintTo(Layout l, std::ostream* os) { *os << layout_name(l); }
inline void PrintTo(CullReason r, std::ostream* os) { *os << cull_reason_name(r); }
inline void PrintTo(const AccessState& s, std::ostream* os) {
  *os << stage_names(s.stages) << "/" << access_names(s.access) << "/" << layout_name(s.layout);
}
}  // namespace volgraph

namespace volgraph::test {

struct Combo {
  const char* name;
  CompileOptions options;
};

inline const std::vector<Combo>& combos() {
  static const std::vector<Combo> all = {
      {"default", CompileOptions{}},
      {"no_cull", CompileOptions{false, true, false}},
      {"no_alias", CompileOptions{true, false, false}},
      {"serialize", CompileOptions{true, true, true}},
  };
  return all;
}

// The generator options a seed stands for (sizes 1..max_passes, small ones often).
inline RandomGraphOptions options_for_seed(uint64_t seed, uint32_t max_passes = 200) {
  Rng meta(seed * 0x9e3779b97f4a7c15ull + 0x632be59bd9b4e019ull);
  RandomGraphOptions o;
  o.seed = seed;
  o.passes = meta.chance(0.35) ? 1 + static_cast<uint32_t>(meta.below(20))
                               : 1 + static_cast<uint32_t>(meta.below(max_passes));
  static const std::vector<uint32_t> kLocality = {1, 2, 4, 8, 8, 16, 64};
  static const std::vector<double> kOutputs = {0.02, 0.05, 0.05, 0.15, 0.4};
  o.locality = meta.pick(kLocality);
  o.output_fraction = meta.pick(kOutputs);
  o.allow_needs = meta.chance(0.85);
  o.allow_inout = meta.chance(0.85);
  o.allow_persistent = meta.chance(0.8);
  static const std::vector<double> kStale = {0.0, 0.05, 0.05, 0.2};
  o.stale_fraction = meta.pick(kStale);
  return o;
}

// A requirements function unlike the default one: several heap classes and coarse alignments.
inline MemoryRequirements coarse_requirements(uint32_t, const ResourceDesc& d) {
  MemoryRequirements m;
  const uint64_t bytes = content_bytes(d) == 0 ? 1 : content_bytes(d);
  auto round_up = [](uint64_t x, uint64_t a) { return (x + a - 1) / a * a; };
  if (d.kind == ResourceKind::buffer) {
    m.heap_class = 1;
    m.alignment = 256;
  } else {
    m.heap_class = format_info(d.format).is_depth ? 3 : (d.kind == ResourceKind::texture3d ? 2 : 0);
    m.alignment = 65536;
  }
  m.size = round_up(bytes, m.alignment);
  return m;
}

// One heap class for everything: buffers and images alias each other. (Mixed alignments
// in one class are covered by HandBuilt.AliasedNeverExceedsUnaliasedWithMixedAlignments.)
inline MemoryRequirements unified_requirements(uint32_t, const ResourceDesc& d) {
  MemoryRequirements m;
  m.heap_class = 0;
  m.alignment = 16384;
  const uint64_t bytes = content_bytes(d) == 0 ? 1 : content_bytes(d);
  m.size = (bytes + m.alignment - 1) / m.alignment * m.alignment;
  return m;
}

// Seeds rotate through the default estimate, coarse and unified requirements.
inline const char* requirements_name(uint64_t seed) {
  switch (seed % 4) {
    case 1: return "coarse";
    case 3: return "unified";
    default: return "estimate";
  }
}

inline RequirementsFn requirements_for_seed(uint64_t seed) {
  switch (seed % 4) {
    case 1: return coarse_requirements;
    case 3: return unified_requirements;
    default: return {};
  }
}

inline uint64_t env_u64(const char* name, uint64_t fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  return std::strtoull(v, nullptr, 10);
}

inline std::string describe(uint64_t seed, const RandomGraphOptions& o, const char* combo) {
  std::ostringstream os;
  os << "seed=" << seed << " passes=" << o.passes << " locality=" << o.locality
     << " output_fraction=" << o.output_fraction << " needs=" << o.allow_needs << " inout=" << o.allow_inout
     << " persistent=" << o.allow_persistent << " stale=" << o.stale_fraction << " requirements=" << requirements_name(seed)
     << " options=" << combo << "\n  reproduce: VOLGRAPH_PROPERTY_SEED=" << seed
     << " ./property_tests --gtest_filter='RandomPlansRepro.OneSeed'"
     << " (VOLGRAPH_PROPERTY_COMBO=0..3 picks default/no_cull/no_alias/serialize)";
  return os.str();
}

// Aspects of two plans to compare.
enum Aspect : uint32_t {
  kOrder = 1,
  kCulled = 2,
  kLifetimes = 4,
  kPlacements = 8,  // placements and heaps
  kHandovers = 16,
  kBarriers = 32,   // barriers and each pass's barrier range
  kMemory = 64,
  kAll = 127,
};

// The first difference between two plans in the given aspects, or "" when equal.
inline std::string plan_difference(const Plan& a, const Plan& b, uint32_t aspects) {
  std::ostringstream os;
  if (aspects & kOrder) {
    if (a.order.size() != b.order.size()) return "order sizes differ";
    for (size_t i = 0; i < a.order.size(); ++i) {
      if (a.order[i].pass != b.order[i].pass) {
        os << "order differs at position " << i << ": pass #" << a.order[i].pass << " vs #" << b.order[i].pass;
        return os.str();
      }
    }
    if (a.position != b.position) return "positions differ";
  }
  if (aspects & kCulled) {
    if (a.culled.size() != b.culled.size()) return "culled sizes differ";
    for (size_t i = 0; i < a.culled.size(); ++i) {
      if (a.culled[i].pass != b.culled[i].pass || a.culled[i].reason != b.culled[i].reason ||
          a.culled[i].missing != b.culled[i].missing || a.culled[i].slot != b.culled[i].slot) {
        os << "culled entry " << i << " differs: #" << a.culled[i].pass << " vs #" << b.culled[i].pass;
        return os.str();
      }
    }
  }
  if (aspects & kLifetimes) {
    if (a.lifetimes.size() != b.lifetimes.size()) return "lifetime sizes differ";
    for (size_t r = 0; r < a.lifetimes.size(); ++r) {
      if (a.lifetimes[r].first != b.lifetimes[r].first || a.lifetimes[r].last != b.lifetimes[r].last) {
        os << "lifetime of resource #" << r << " differs";
        return os.str();
      }
    }
  }
  if (aspects & kPlacements) {
    if (a.placements.size() != b.placements.size()) return "placement sizes differ";
    for (size_t r = 0; r < a.placements.size(); ++r) {
      const Placement& x = a.placements[r];
      const Placement& y = b.placements[r];
      if (x.heap != y.heap || x.offset != y.offset || x.requirements.size != y.requirements.size ||
          x.requirements.alignment != y.requirements.alignment ||
          x.requirements.heap_class != y.requirements.heap_class) {
        os << "placement of resource #" << r << " differs: heap " << x.heap << " @" << x.offset << " vs heap "
           << y.heap << " @" << y.offset;
        return os.str();
      }
    }
    if (a.heaps.size() != b.heaps.size()) return "heap counts differ";
    for (size_t h = 0; h < a.heaps.size(); ++h) {
      if (a.heaps[h].heap_class != b.heaps[h].heap_class || a.heaps[h].size != b.heaps[h].size ||
          a.heaps[h].alignment != b.heaps[h].alignment) {
        os << "heap " << h << " differs";
        return os.str();
      }
    }
  }
  if (aspects & kHandovers) {
    if (a.handovers.size() != b.handovers.size()) return "handover counts differ";
    for (size_t i = 0; i < a.handovers.size(); ++i) {
      if (a.handovers[i].resource != b.handovers[i].resource || a.handovers[i].previous != b.handovers[i].previous) {
        os << "handover " << i << " differs";
        return os.str();
      }
    }
  }
  if (aspects & kBarriers) {
    if (a.barriers.size() != b.barriers.size()) return "barrier counts differ";
    for (size_t k = 0; k < a.barriers.size(); ++k) {
      const Barrier& x = a.barriers[k];
      const Barrier& y = b.barriers[k];
      if (x.resource != y.resource || !(x.from == y.from) || !(x.to == y.to) || x.aliasing != y.aliasing) {
        os << "barrier " << k << " differs";
        return os.str();
      }
    }
    if (a.order.size() == b.order.size()) {
      for (size_t i = 0; i < a.order.size(); ++i) {
        if (a.order[i].barrier_begin != b.order[i].barrier_begin ||
            a.order[i].barrier_count != b.order[i].barrier_count) {
          os << "barrier range at position " << i << " differs";
          return os.str();
        }
      }
    }
  }
  if (aspects & kMemory) {
    const MemoryStats& x = a.memory;
    const MemoryStats& y = b.memory;
    if (x.unaliased_bytes != y.unaliased_bytes || x.aliased_bytes != y.aliased_bytes ||
        x.lower_bound_bytes != y.lower_bound_bytes || x.persistent_bytes != y.persistent_bytes ||
        x.transient_count != y.transient_count) {
      return "memory stats differ";
    }
  }
  return "";
}

// The first few violations, one per line, for a failure message.
inline std::string first_violations(const std::vector<std::string>& v, size_t n = 12) {
  std::string out;
  for (size_t i = 0; i < v.size() && i < n; ++i) out += "  " + v[i] + "\n";
  if (v.size() > n) out += "  ... " + std::to_string(v.size() - n) + " more\n";
  return out;
}

}  // namespace volgraph::test
