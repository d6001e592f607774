// Transient memory: each resource gets bytes in a heap of its class; two resources
// share bytes only when their lifetimes are disjoint. Placement is greedy by size
// with best fit among the gaps left by resources alive at the same time.
#include <algorithm>
#include <map>
#include <memory_resource>

#include "graph/compiler/steps.h"

namespace volgraph::compiler {
uint64_t align_up(uint64_t v, uint64_t a) {
  if ((a & (a - 1)) == 0) return (v + a - 1) & ~(a - 1);  // a power of two (every backend's): no division
  return (v + a - 1) / a * a;
}

namespace {

bool overlaps(const Lifetime& a, const Lifetime& b) { return a.first <= b.last && b.first <= a.last; }

struct Item {
  uint32_t resource;
  Lifetime life;
  MemoryRequirements req;
};

uint64_t heap_size(const std::vector<Item>& items, const std::vector<uint64_t>& offset) {
  uint64_t size = 0;
  for (size_t i = 0; i < items.size(); ++i) size = std::max(size, offset[i] + items[i].req.size);
  return size;
}

// Item indices in order of a key, sorted by value (no lookups through the index while
// sorting). Items are in resource order, so the index breaks ties as the resource would.
template <typename Key>
std::vector<uint32_t> sorted_by(const std::vector<Item>& items, Key key) {
  using K = decltype(key(items[0]));
  std::vector<std::pair<K, uint32_t>> keyed(items.size());
  for (uint32_t i = 0; i < items.size(); ++i) keyed[i] = {key(items[i]), i};
  std::sort(keyed.begin(), keyed.end());
  std::vector<uint32_t> order(items.size());
  for (size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].second;
  return order;
}

// Placed items by the time buckets their lifetimes cover, as compressed rows built up
// front (every lifetime is known); an item counts once placed. Items living longer
// than kLong buckets are kept apart and scanned once per query, not once per bucket.
class TimeIndex {
 public:
  TimeIndex(const std::vector<Item>& items, uint32_t positions)
      : items_(items), begin_(positions / kWidth + 2, 0), placed_(items.size(), 0), seen_(items.size(), 0) {
    auto buckets = [](const Item& it) { return it.life.last / kWidth - it.life.first / kWidth + 1; };
    for (const Item& it : items) {
      if (buckets(it) > kLong) continue;
      for (uint32_t b = it.life.first / kWidth; b <= it.life.last / kWidth; ++b) ++begin_[b + 1];
    }
    for (size_t b = 1; b < begin_.size(); ++b) begin_[b] += begin_[b - 1];
    entries_.resize(begin_.back());
    std::vector<uint32_t> fill(begin_.begin(), begin_.end() - 1);
    for (uint32_t i = 0; i < items.size(); ++i) {
      if (buckets(items[i]) > kLong) continue;
      for (uint32_t b = items[i].life.first / kWidth; b <= items[i].life.last / kWidth; ++b) entries_[fill[b]++] = i;
    }
  }

  void place(uint32_t item) {
    placed_[item] = 1;
    const Lifetime& l = items_[item].life;
    if (l.last / kWidth - l.first / kWidth + 1 > kLong) long_lived_.push_back(item);
  }

  // Placed items whose lifetime overlaps `life` (each once).
  template <typename F>
  void for_each_overlapping(const Lifetime& life, F&& f) {
    for (uint32_t i : long_lived_) {
      if (overlaps(items_[i].life, life)) f(i);
    }
    ++stamp_;
    for (uint32_t b = life.first / kWidth; b <= life.last / kWidth; ++b) {
      for (uint32_t k = begin_[b]; k < begin_[b + 1]; ++k) {
        const uint32_t i = entries_[k];
        if (!placed_[i] || seen_[i] == stamp_ || !overlaps(items_[i].life, life)) continue;
        seen_[i] = stamp_;
        f(i);
      }
    }
  }

 private:
  static constexpr uint32_t kWidth = 16;
  static constexpr uint32_t kLong = 4;
  const std::vector<Item>& items_;
  std::vector<uint32_t> begin_, entries_, long_lived_;
  std::vector<uint8_t> placed_;
  std::vector<uint32_t> seen_;
  uint32_t stamp_ = 0;
};

// The lowest-waste offset for `item` among gaps between `busy` ranges (sorted by offset).
uint64_t best_fit(const Item& item, const std::vector<std::pair<uint64_t, uint64_t>>& busy) {
  const uint64_t size = item.req.size;
  const uint64_t align = item.req.alignment;
  uint64_t cursor = 0, best = UINT64_MAX, best_gap = UINT64_MAX;
  for (const auto& [begin, end] : busy) {
    const uint64_t start = align_up(cursor, align);
    if (begin > start && begin - start >= size && begin - start < best_gap) {
      best_gap = begin - start;
      best = start;
    }
    cursor = std::max(cursor, end);
  }
  return best != UINT64_MAX ? best : align_up(cursor, align);
}

// Greedy by size keeps to the lower bound far better than a linear scan, and costs
// time in proportion to the pairs of resources alive together; past this many pairs
// per resource on average the linear scan takes over.
constexpr uint64_t kGreedyPairsPerResource = 16;

std::vector<uint64_t> place_aliased(std::vector<Item>& items, uint32_t positions) {
  const std::vector<uint32_t> by_size =
      sorted_by(items, [](const Item& it) { return std::pair{~it.req.size, it.life.first}; });  // larger first
  std::vector<uint64_t> offset(items.size(), 0);
  TimeIndex index(items, positions);
  std::vector<std::pair<uint64_t, uint64_t>> busy;
  for (uint32_t i : by_size) {
    busy.clear();
    index.for_each_overlapping(items[i].life, [&](uint32_t j) { busy.emplace_back(offset[j], offset[j] + items[j].req.size); });
    std::sort(busy.begin(), busy.end());
    offset[i] = best_fit(items[i], busy);
    index.place(i);
  }
  return offset;
}

// The distinct alignments of `items`, strictest first, when there are at most
// kFewAlignments of them (a backend has a handful); empty otherwise.
constexpr size_t kFewAlignments = 16;
std::vector<uint64_t> few_alignments_strictest_first(const std::vector<Item>& items) {
  std::vector<uint64_t> out;
  for (const Item& it : items) {
    if (std::find(out.begin(), out.end(), it.req.alignment) != out.end()) continue;
    if (out.size() == kFewAlignments) return {};
    out.push_back(it.req.alignment);
  }
  std::sort(out.begin(), out.end(), std::greater<>());
  return out;
}

// Side by side, strictest alignment first so that padding stays rare.
std::vector<uint64_t> place_unaliased(const std::vector<Item>& items) {
  std::vector<uint32_t> by_alignment(items.size());
  for (uint32_t i = 0; i < items.size(); ++i) by_alignment[i] = i;
  std::stable_sort(by_alignment.begin(), by_alignment.end(),
                   [&](uint32_t a, uint32_t b) { return items[a].req.alignment > items[b].req.alignment; });
  std::vector<uint64_t> offset(items.size());
  uint64_t cursor = 0;
  for (uint32_t i : by_alignment) {
    offset[i] = align_up(cursor, items[i].req.alignment);
    cursor = offset[i] + items[i].req.size;
  }
  return offset;
}

// A linear scan in order of first use: each resource takes the best-fitting free
// block (or the top of the heap) and gives its block back after its last use.
// O(n log n) whatever the lifetimes, at the price of some fragmentation.
// The free blocks are few (the holes between resources alive at once): one flat array
// sorted by start, searched linearly for the best fit, beats two balanced trees.
class FreeList {
 public:
  // Where a block of `size` aligned to `align` goes: the smallest free block it fits
  // in (the lowest such when several are as small), else the top of the heap (reusing
  // a free block that reaches the top).
  uint64_t take(uint64_t size, uint64_t align) {
    size_t best = blocks_.size();
    for (size_t i = 0; i < blocks_.size(); ++i) {
      const Block& b = blocks_[i];
      if (b.length < size || (best != blocks_.size() && b.length >= blocks_[best].length)) continue;
      if (align_up(b.start, align) + size > b.start + b.length) continue;
      best = i;
      if (b.length == size) break;  // an exact fit: none smaller, and the lowest of its length
    }
    if (best != blocks_.size()) {
      const Block b = blocks_[best];
      const uint64_t at = align_up(b.start, align);
      replace(best, {b.start, at - b.start}, {at + size, b.start + b.length - at - size});
      return at;
    }
    uint64_t at = align_up(top_, align);
    if (!blocks_.empty() && blocks_.back().start + blocks_.back().length == top_) {
      const Block last = blocks_.back();
      blocks_.pop_back();
      at = align_up(last.start, align);
      if (at > last.start) blocks_.push_back({last.start, at - last.start});
    }
    top_ = std::max(top_, at + size);
    return at;
  }

  // Returns a block, merged with free neighbours that touch it.
  void give_back(uint64_t start, uint64_t length) {
    const auto next = std::lower_bound(blocks_.begin(), blocks_.end(), start, [](const Block& b, uint64_t s) { return b.start < s; });
    const bool joins_next = next != blocks_.end() && next->start == start + length;
    const bool joins_previous = next != blocks_.begin() && std::prev(next)->start + std::prev(next)->length == start;
    if (joins_previous) {
      std::prev(next)->length += length + (joins_next ? next->length : 0);
      if (joins_next) blocks_.erase(next);
    } else if (joins_next) {
      next->length += length;
      next->start = start;
    } else {
      blocks_.insert(next, {start, length});
    }
  }

 private:
  struct Block {
    uint64_t start, length;
  };

  // Block i gives way to what is left of it on either side (empty parts dropped),
  // moving the array only when the count of blocks changes.
  void replace(size_t i, Block left, Block right) {
    const auto at = blocks_.begin() + ptrdiff_t(i);
    if (left.length && right.length) {
      *at = right;
      blocks_.insert(at, left);
    } else if (left.length || right.length) {
      *at = left.length ? left : right;
    } else {
      blocks_.erase(at);
    }
  }

  std::vector<Block> blocks_;  // sorted by start, disjoint, never touching
  uint64_t top_ = 0;
};

std::vector<uint64_t> place_linear_scan(const std::vector<Item>& items) {
  // First use, larger first; the order of releases at one position changes nothing (the
  // free blocks merge the same way).
  const std::vector<uint32_t> by_first =
      sorted_by(items, [](const Item& it) { return std::pair{it.life.first, ~it.req.size}; });
  const std::vector<uint32_t> by_last = sorted_by(items, [](const Item& it) { return it.life.last; });
  std::vector<uint64_t> offset(items.size(), 0);
  FreeList heap;
  size_t released = 0;
  for (uint32_t i : by_first) {
    for (; released < by_last.size() && items[by_last[released]].life.last < items[i].life.first; ++released) {
      const uint32_t j = by_last[released];
      heap.give_back(offset[j], items[j].req.size);
    }
    offset[i] = heap.take(items[i].req.size, items[i].req.alignment);
  }
  return offset;
}

// The linear scan run backwards in time (lifetimes mirrored: the last use becomes the
// first), which fragments differently; the offsets hold for the original lifetimes, as
// mirroring keeps which lifetimes overlap.
std::vector<uint64_t> place_linear_scan_mirrored(const std::vector<Item>& items) {
  uint32_t end = 0;
  for (const Item& it : items) end = std::max(end, it.life.last);
  std::vector<Item> mirrored = items;
  for (Item& it : mirrored) it.life = {end - it.life.last, end - it.life.first};
  return place_linear_scan(mirrored);
}

// The linear scan forwards and, when that leaves more than 1 % above `lower_bound`,
// backwards too; the smaller layout (forwards on a tie).
std::vector<uint64_t> place_linear_scan_both_ways(const std::vector<Item>& items, uint64_t lower_bound) {
  std::vector<uint64_t> forwards = place_linear_scan(items);
  const uint64_t forwards_size = heap_size(items, forwards);
  if (forwards_size - forwards_size / 101 <= lower_bound) return forwards;  // forwards ≤ 1.01 × lower bound
  std::vector<uint64_t> backwards = place_linear_scan_mirrored(items);
  return heap_size(items, backwards) < forwards_size ? backwards : forwards;
}

// How many pairs of resources are alive at a common position: greedy-by-size visits
// each such pair, so it stays the method only while they are few.
uint64_t overlapping_pairs(const std::vector<Item>& items, uint32_t positions) {
  std::vector<uint64_t> started(positions + 1, 0), ended(positions + 1, 0);  // counts up to a position
  for (const Item& it : items) {
    ++started[it.life.first];
    ++ended[it.life.last];
  }
  for (uint32_t p = 1; p <= positions; ++p) {
    started[p] += started[p - 1];
    ended[p] += ended[p - 1];
  }
  uint64_t pairs = 0;  // for each resource: started by its last position − ended before its first
  for (const Item& it : items) pairs += started[it.life.last] - (it.life.first ? ended[it.life.first - 1] : 0) - 1;
  return pairs / 2;
}

// The size of place_unaliased's layout without making it: the same walk, strictest
// alignment first and in item order within one alignment.
uint64_t unaliased_size(const std::vector<Item>& items) {
  const std::vector<uint64_t> alignments = few_alignments_strictest_first(items);
  if (alignments.empty()) return heap_size(items, place_unaliased(items));
  uint64_t cursor = 0;
  for (const uint64_t alignment : alignments) {
    for (const Item& it : items) {
      if (it.req.alignment == alignment) cursor = align_up(cursor, alignment) + it.req.size;
    }
  }
  return cursor;
}


// The most bytes alive at one position: no placement can do better.
uint64_t live_bytes_peak(const std::vector<Item>& items, uint32_t positions) {
  std::vector<int64_t> delta(positions + 2, 0);
  for (const Item& it : items) {
    delta[it.life.first] += static_cast<int64_t>(it.req.size);
    delta[it.life.last + 1] -= static_cast<int64_t>(it.req.size);
  }
  int64_t live = 0, peak = 0;
  for (int64_t d : delta) peak = std::max(peak, live += d);
  return static_cast<uint64_t>(peak);
}

// Sweeps the heap in order of first use; the latest occupant of each byte range is
// the one a new resource hands over from.
void find_handovers(const std::vector<Item>& items, const std::vector<uint64_t>& offset, std::vector<Handover>& out) {
  const std::vector<uint32_t> by_start = sorted_by(items, [](const Item& it) { return it.life.first; });
  struct Segment {
    uint64_t end;
    uint32_t item;  // the last resource to use [start, end)
  };
  std::pmr::monotonic_buffer_resource arena;
  std::pmr::map<uint64_t, Segment> occupied(&arena);  // start → segment; disjoint
  std::vector<uint32_t> previous;
  for (uint32_t i : by_start) {
    const uint64_t begin = offset[i], end = begin + items[i].req.size;
    if (end == begin) continue;
    previous.clear();
    auto it = occupied.upper_bound(begin);
    if (it != occupied.begin() && std::prev(it)->second.end > begin) --it;
    while (it != occupied.end() && it->first < end) {
      const uint64_t start = it->first;
      const Segment seg = it->second;
      previous.push_back(seg.item);
      it = occupied.erase(it);
      if (start < begin) occupied.emplace(start, Segment{begin, seg.item});
      if (seg.end > end) it = occupied.emplace(end, Segment{seg.end, seg.item}).first;
    }
    occupied.emplace(begin, Segment{end, i});
    std::sort(previous.begin(), previous.end());
    previous.erase(std::unique(previous.begin(), previous.end()), previous.end());
    for (uint32_t p : previous) out.push_back({items[i].resource, items[p].resource});
  }
}

}  // namespace

MemoryLayout place_memory(const Graph& graph, const std::vector<Lifetime>& lifetimes, bool alias,
                          const RequirementsFn& requirements) {
  MemoryLayout m;
  m.placements.resize(graph.resources.size());
  uint32_t positions = 0;
  std::map<uint32_t, std::vector<Item>> by_class;
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {
    const Lifetime& life = lifetimes[r];
    if (life.first == kNone) continue;
    const ResourceDesc& desc = graph.resources[r].desc;
    MemoryRequirements req = requirements ? requirements(r, desc) : estimate_requirements(desc);
    req.alignment = std::max<uint64_t>(1, req.alignment);
    m.placements[r].requirements = req;
    if (desc.persistent) {
      m.stats.persistent_bytes += req.size;
      continue;
    }
    positions = std::max(positions, life.last + 1);
    by_class[req.heap_class].push_back({r, life, req});
  }
  for (auto& [heap_class, items] : by_class) {
    const PlacementMethod method = !alias ? PlacementMethod::unaliased
                                   : overlapping_pairs(items, positions) <= kGreedyPairsPerResource * items.size()
                                       ? PlacementMethod::greedy_by_size
                                       : PlacementMethod::linear_scan;
    // Side by side is what --no-alias allocates; an aliased layout that padding made
    // larger (mixed alignments) gives way to it.
    const uint64_t side_by_side_size = unaliased_size(items);
    const uint64_t lower_bound = live_bytes_peak(items, positions);
    std::vector<uint64_t> offset = method == PlacementMethod::greedy_by_size ? place_aliased(items, positions)
                                   : method == PlacementMethod::linear_scan  ? place_linear_scan_both_ways(items, lower_bound)
                                                                             : place_unaliased(items);
    if (method != PlacementMethod::unaliased && heap_size(items, offset) > side_by_side_size) offset = place_unaliased(items);
    m.stats.method = std::max(m.stats.method, method);
    Heap heap{heap_class, heap_size(items, offset), 1};
    const uint32_t heap_index = static_cast<uint32_t>(m.heaps.size());
    for (size_t i = 0; i < items.size(); ++i) {
      Placement& p = m.placements[items[i].resource];
      p.heap = heap_index;
      p.offset = offset[i];
      heap.alignment = std::max(heap.alignment, items[i].req.alignment);
    }
    m.stats.unaliased_bytes += side_by_side_size;
    m.stats.transient_count += items.size();
    m.stats.aliased_bytes += heap.size;
    m.stats.lower_bound_bytes += lower_bound;
    m.heaps.push_back(heap);
    if (alias) find_handovers(items, offset, m.handovers);
  }
  return m;
}

}  // namespace volgraph::compiler

namespace volgraph {

MemoryRequirements estimate_requirements(const ResourceDesc& desc) {
  // Typical of desktop drivers: 64 KiB for optimal-tiling images, 256 B for buffers,
  // and buffers kept apart from images (buffer-image granularity).
  const bool buffer = desc.kind == ResourceKind::buffer;
  const uint64_t alignment = buffer ? 256 : 65536;
  return {compiler::align_up(std::max<uint64_t>(1, content_bytes(desc)), alignment), alignment, buffer ? 1u : 0u};
}

}  // namespace volgraph
