#include "tests/support/random_graph.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>

namespace volgraph::test {

uint64_t Rng::below(uint64_t n) {
  if (n <= 1) return 0;
  // Rejection sampling on the top of the 64-bit range: exact and portable.
  const uint64_t limit = ~uint64_t{0} - (~uint64_t{0} % n);
  for (;;) {
    const uint64_t x = next();
    if (x < limit) return x % n;
  }
}

namespace {

// The resources a slot may take, as classes: what matters for wiring is the kind and
// whether the format is a depth format.
enum Cls : uint32_t { kColor2d = 0, kDepth2d = 1, kTex3d = 2, kBuffer = 3, kClassCount = 4 };
constexpr uint32_t bit(Cls c) { return 1u << c; }

uint32_t class_of(const ResourceDesc& desc) {
  switch (desc.kind) {
    case ResourceKind::buffer: return kBuffer;
    case ResourceKind::texture3d: return kTex3d;
    case ResourceKind::texture2d: return format_info(desc.format).is_depth ? kDepth2d : kColor2d;
  }
  return kColor2d;
}

// Which classes a slot of (kind, usage) accepts.
uint32_t accepted_classes(ResourceKind kind, Usage usage) {
  if (kind == ResourceKind::buffer) return bit(kBuffer);
  if (kind == ResourceKind::texture3d) return bit(kTex3d);
  switch (usage) {
    case Usage::depth_read:
    case Usage::depth_attachment:
      return bit(kDepth2d);
    case Usage::storage_read:
    case Usage::storage_write:
    case Usage::storage_read_write:
    case Usage::color_attachment:
    case Usage::color_attachment_load:
      return bit(kColor2d);
    default:
      return bit(kColor2d) | bit(kDepth2d);
  }
}

const std::vector<Format> kStorageFormats = {Format::rgba8_unorm, Format::rgba16_float, Format::r32_float,
                                             Format::rg32_float,  Format::rgba32_float, Format::r32_uint};
const std::vector<Format> kColorFormats = {Format::rgba8_unorm,  Format::rgba8_srgb,   Format::r16_float,
                                           Format::rg16_float,   Format::rgba16_float, Format::r32_float,
                                           Format::rgba32_float, Format::r11g11b10_float, Format::r8_unorm};

ResourceKind random_kind(Rng& rng, uint32_t w2d, uint32_t w3d, uint32_t wbuf) {
  const uint64_t x = rng.below(w2d + w3d + wbuf);
  if (x < w2d) return ResourceKind::texture2d;
  if (x < w2d + w3d) return ResourceKind::texture3d;
  return ResourceKind::buffer;
}

SizeSpec random_size(Rng& rng, ResourceKind kind) {
  static const std::vector<float> kScales = {0.25f, 0.5f, 1.0f, 1.0f, 2.0f};
  static const std::vector<uint32_t> kSides = {64, 128, 256, 512, 1024, 2048};
  static const std::vector<uint32_t> kSides3d = {32, 64, 128, 160};
  static const std::vector<uint32_t> kDepths3d = {16, 32, 64, 128};
  switch (kind) {
    case ResourceKind::texture2d:
      if (rng.chance(0.6)) {
        const float sx = rng.pick(kScales);
        const float sy = rng.chance(0.8) ? sx : rng.pick(kScales);
        return SizeSpec::of_output(sx, sy);
      }
      return SizeSpec::fixed(rng.pick(kSides), rng.pick(kSides));
    case ResourceKind::texture3d:
      if (rng.chance(0.3)) {
        const float s = rng.chance(0.5) ? 0.125f : 0.0625f;
        return SizeSpec::of_output(s, s, rng.pick(kDepths3d));
      }
      return SizeSpec::fixed(rng.pick(kSides3d), rng.pick(kSides3d), rng.pick(kDepths3d));
    case ResourceKind::buffer: {
      // 4 KiB .. 32 MiB, sometimes not a power of two.
      uint64_t bytes = uint64_t{4096} << rng.below(14);
      if (rng.chance(0.3)) bytes += 256 * rng.below(64);
      return SizeSpec::bytes(bytes);
    }
  }
  return {};
}

SlotDecl random_input(Rng& rng, PassKind pass_kind, int index) {
  const std::string name = "in" + std::to_string(index);
  ResourceKind kind = random_kind(rng, 50, 20, 30);
  Usage usage = Usage::sampled;
  switch (pass_kind) {
    case PassKind::compute:
      if (kind == ResourceKind::buffer) {
        usage = rng.chance(0.5) ? Usage::storage_read : Usage::uniform_read;
      } else {
        usage = rng.chance(0.6) ? Usage::sampled : Usage::storage_read;
      }
      break;
    case PassKind::graphics:
      if (kind == ResourceKind::buffer) {
        usage = rng.chance(0.5) ? Usage::storage_read : Usage::uniform_read;
      } else if (kind == ResourceKind::texture2d) {
        const uint64_t x = rng.below(100);
        usage = x < 50 ? Usage::sampled : (x < 65 ? Usage::storage_read : Usage::depth_read);
      } else {
        usage = rng.chance(0.7) ? Usage::sampled : Usage::storage_read;
      }
      break;
    case PassKind::transfer:
      usage = Usage::copy_src;
      break;
  }
  SlotDecl s = slot_in(name, kind, usage, "random input");
  s.optional = rng.chance(0.25);
  return s;
}

SlotDecl random_inout(Rng& rng, PassKind pass_kind) {
  ResourceKind kind = ResourceKind::texture2d;
  Usage usage = Usage::storage_read_write;
  switch (pass_kind) {
    case PassKind::compute:
      kind = random_kind(rng, 45, 25, 30);
      usage = Usage::storage_read_write;
      break;
    case PassKind::graphics: {
      kind = random_kind(rng, 70, 15, 15);
      if (kind == ResourceKind::texture2d) {
        const uint64_t x = rng.below(100);
        usage = x < 45 ? Usage::color_attachment_load : (x < 80 ? Usage::depth_attachment : Usage::storage_read_write);
      }
      break;
    }
    case PassKind::transfer:
      kind = random_kind(rng, 40, 20, 40);
      usage = Usage::copy_dst;
      break;
  }
  return slot_inout("io", kind, usage, "random inout");
}

SlotDecl random_output(Rng& rng, PassKind pass_kind, int index, bool allow_persistent) {
  const std::string name = "out" + std::to_string(index);
  ResourceKind kind = ResourceKind::texture2d;
  Usage usage = Usage::storage_write;
  Format format = Format::undefined;
  switch (pass_kind) {
    case PassKind::compute:
      kind = random_kind(rng, 45, 20, 35);
      usage = Usage::storage_write;
      if (kind != ResourceKind::buffer) format = rng.pick(kStorageFormats);
      break;
    case PassKind::graphics:
      kind = ResourceKind::texture2d;
      if (rng.chance(0.25)) {
        usage = Usage::depth_attachment;
        format = Format::d32_float;
      } else {
        usage = Usage::color_attachment;
        format = rng.pick(kColorFormats);
      }
      break;
    case PassKind::transfer:
      kind = random_kind(rng, 40, 20, 40);
      usage = Usage::copy_dst;
      if (kind != ResourceKind::buffer) format = rng.pick(kColorFormats);
      break;
  }
  SlotDecl s = slot_out(name, kind, usage, format, random_size(rng, kind), "random output");
  s.persistent = allow_persistent && rng.chance(0.08);
  return s;
}

SceneFeatures random_needs(Rng& rng) {
  const uint32_t n = static_cast<uint32_t>(SceneFeature::count);
  SceneFeatures needs = 1u << rng.below(n);
  if (rng.chance(0.25)) needs |= 1u << rng.below(n);
  return needs;
}

std::unique_ptr<PassDecl> random_decl(Rng& rng, int index, const RandomGraphOptions& options) {
  auto d = std::make_unique<PassDecl>();
  const uint64_t k = rng.below(100);
  d->kind = k < 45 ? PassKind::compute : (k < 80 ? PassKind::graphics : PassKind::transfer);
  d->name = std::string(pass_kind_name(d->kind)) + std::to_string(index);
  d->variants.push_back({"default", ""});
  const uint64_t w = rng.below(100);
  const int inputs = w < 10 ? 0 : (w < 45 ? 1 : (w < 80 ? 2 : 3));
  for (int i = 0; i < inputs; ++i) d->slots.push_back(random_input(rng, d->kind, i));
  if (options.allow_inout && rng.chance(0.35)) d->slots.push_back(random_inout(rng, d->kind));
  const int outputs = rng.chance(0.7) ? 1 : 2;
  for (int i = 0; i < outputs; ++i) d->slots.push_back(random_output(rng, d->kind, i, options.allow_persistent));
  // A temporal pass: reads last frame's content of its first output (a texture) as history.
  const SlotDecl& first = d->slots[d->slots.size() - size_t(outputs)];
  if (options.allow_persistent && d->kind != PassKind::transfer && first.kind != ResourceKind::buffer && rng.chance(0.15)) {
    d->slots.push_back(slot_history("history", first.name, "random history"));
  }
  if (options.allow_needs && rng.chance(0.3)) d->needs = random_needs(rng);
  return d;
}

// Two source decls so that every class of resource can appear from the start.
std::unique_ptr<PassDecl> source_graphics(Rng& rng, const RandomGraphOptions& options) {
  auto d = std::make_unique<PassDecl>();
  d->name = "gbuffer_source";
  d->kind = PassKind::graphics;
  d->variants.push_back({"default", ""});
  d->slots.push_back(slot_out("color", ResourceKind::texture2d, Usage::color_attachment, rng.pick(kColorFormats),
                              SizeSpec::of_output(), "color"));
  d->slots.push_back(slot_out("depth", ResourceKind::texture2d, Usage::depth_attachment, Format::d32_float,
                              SizeSpec::of_output(), "depth"));
  if (options.allow_needs && rng.chance(0.3)) d->needs = random_needs(rng);
  return d;
}

std::unique_ptr<PassDecl> source_compute(Rng& rng, const RandomGraphOptions& options) {
  auto d = std::make_unique<PassDecl>();
  d->name = "volume_source";
  d->kind = PassKind::compute;
  d->variants.push_back({"default", ""});
  d->slots.push_back(slot_out("params", ResourceKind::buffer, Usage::storage_write, Format::undefined,
                              random_size(rng, ResourceKind::buffer), "buffer"));
  d->slots.push_back(slot_out("volume", ResourceKind::texture3d, Usage::storage_write, rng.pick(kStorageFormats),
                              random_size(rng, ResourceKind::texture3d), "volume"));
  d->slots.back().persistent = options.allow_persistent && rng.chance(0.2);
  if (options.allow_needs && rng.chance(0.3)) d->needs = random_needs(rng);
  return d;
}

struct Entry {
  uint32_t resource;
  uint32_t seq;  // position in the hidden sequence when it was created or last modified
};

class Wiring {
 public:
  Wiring(Rng& rng, const RandomGraphOptions& options) : rng_(rng), options_(options) {}

  // A resource accepted by `classes`, mostly from recent passes, not in `exclude`; kNone if none.
  uint32_t pick(uint32_t classes, uint32_t seq, const std::vector<uint32_t>& exclude) {
    std::array<uint32_t, kClassCount> order{};
    uint32_t n = 0;
    for (uint32_t c = 0; c < kClassCount; ++c) {
      if ((classes & (1u << c)) && !pools_[c].empty()) order[n++] = c;
    }
    if (n == 0) return kNone;
    // Colour first most of the time when both 2D classes fit.
    if (n == 2 && order[0] == kColor2d && order[1] == kDepth2d && rng_.chance(0.25)) std::swap(order[0], order[1]);
    for (uint32_t i = 0; options_.consume_unread && i < n; ++i) {
      const uint32_t r = oldest_unread(order[i], seq, exclude);
      if (r != kNone) return r;
    }
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t r = pick_in(pools_[order[i]], seq, exclude);
      if (r != kNone) return r;
    }
    return kNone;
  }

  // `resource` got a new latest version (created or modified) at `seq`.
  void touch(uint32_t resource, uint32_t cls, uint32_t seq) {
    pools_[cls].push_back({resource, seq});
    if (!options_.consume_unread) return;
    if (unread_seq_.size() <= resource) unread_seq_.resize(resource + 1, kNone);
    unread_seq_[resource] = seq;
    unread_[cls].push_back({resource, seq});
  }

  // A pass read or modified `resource`'s latest version: its writer feeds a later pass.
  void mark_read(uint32_t resource) {
    if (resource >= unread_seq_.size() || unread_seq_[resource] == kNone) return;
    if (fed_.size() <= unread_seq_[resource]) fed_.resize(unread_seq_[resource] + 1, 0);
    fed_[unread_seq_[resource]] = 1;
    unread_seq_[resource] = kNone;
  }

  // Whether `resource`'s latest version is unread and its writer feeds no later pass.
  bool left_by_unfed_pass(uint32_t resource) const {
    if (resource >= unread_seq_.size() || unread_seq_[resource] == kNone) return false;
    return unread_seq_[resource] >= fed_.size() || !fed_[unread_seq_[resource]];
  }

 private:
  uint32_t pick_in(const std::vector<Entry>& pool, uint32_t seq, const std::vector<uint32_t>& exclude) {
    auto excluded = [&](uint32_t r) { return std::find(exclude.begin(), exclude.end(), r) != exclude.end(); };
    const uint32_t from = seq > options_.locality ? seq - options_.locality : 0;
    const auto window = std::lower_bound(pool.begin(), pool.end(), from,
                                         [](const Entry& e, uint32_t s) { return e.seq < s; });
    const size_t window_begin = static_cast<size_t>(window - pool.begin());
    for (int attempt = 0; attempt < 6; ++attempt) {
      size_t i;
      if (window_begin < pool.size() && rng_.chance(0.85)) {
        i = window_begin + rng_.below(pool.size() - window_begin);
      } else {
        i = far_begin(pool, seq) + rng_.below(pool.size() - far_begin(pool, seq));
      }
      if (!excluded(pool[i].resource)) return pool[i].resource;
    }
    for (size_t i = pool.size(); i-- > 0;) {
      if (!excluded(pool[i].resource)) return pool[i].resource;
    }
    return kNone;
  }

  // consume_unread: the oldest resource of class `c` whose latest version no pass has
  // read, made at most far_window passes back by a pass that feeds no later pass yet,
  // not in `exclude`; kNone if none.
  uint32_t oldest_unread(uint32_t c, uint32_t seq, const std::vector<uint32_t>& exclude) {
    const std::vector<Entry>& list = unread_[c];
    const uint32_t from = options_.far_window == 0 || seq <= options_.far_window ? 0 : seq - options_.far_window;
    auto current = [&](const Entry& e) {
      return unread_seq_[e.resource] == e.seq && (e.seq >= fed_.size() || !fed_[e.seq]);
    };
    size_t& head = unread_head_[c];
    while (head < list.size() && (list[head].seq < from || !current(list[head]))) ++head;
    for (size_t i = head; i < list.size(); ++i) {
      if (current(list[i]) && std::find(exclude.begin(), exclude.end(), list[i].resource) == exclude.end()) {
        return list[i].resource;
      }
    }
    return kNone;
  }

  // Where long-range reads may start: the whole pool, or the last far_window passes.
  size_t far_begin(const std::vector<Entry>& pool, uint32_t seq) const {
    if (options_.far_window == 0 || seq <= options_.far_window) return 0;
    const uint32_t from = seq - options_.far_window;
    const auto it = std::lower_bound(pool.begin(), pool.end(), from, [](const Entry& e, uint32_t s) { return e.seq < s; });
    return it == pool.end() ? pool.size() - 1 : static_cast<size_t>(it - pool.begin());
  }

  Rng& rng_;
  const RandomGraphOptions& options_;
  std::array<std::vector<Entry>, kClassCount> pools_;
  // consume_unread: per resource the sequence position of its unread latest version
  // (kNone once read), and per class the latest versions in order made (stale entries
  // skipped), scanned from a head that only moves forward.
  std::vector<uint32_t> unread_seq_;
  std::vector<uint8_t> fed_;  // per sequence position: some version its pass made was read
  std::array<std::vector<Entry>, kClassCount> unread_;
  std::array<size_t, kClassCount> unread_head_{};
};

}  // namespace

RandomGraph make_random_graph(const RandomGraphOptions& options) {
  Rng rng(options.seed);
  RandomGraph out;

  // The decl pool.
  out.decls.push_back(source_graphics(rng, options));
  out.decls.push_back(source_compute(rng, options));
  const int pool_size = 8 + static_cast<int>(rng.below(7));
  for (int i = 2; i < pool_size; ++i) out.decls.push_back(random_decl(rng, i, options));

  SceneFeatures scene = 0;
  for (uint32_t f = 0; f < static_cast<uint32_t>(SceneFeature::count); ++f) {
    if (!options.allow_needs || rng.chance(0.8)) scene |= 1u << f;
  }
  static const std::vector<Extent> kOutputs = {{320, 180, 1}, {1280, 720, 1}, {1920, 1080, 1}};
  const Extent output_size = rng.pick(kOutputs);

  // Phase 1: the hidden sequence of decls. A decl fits once every class its required
  // slots take has appeared; availability only grows, so the fitting list is rebuilt
  // at most once per class.
  auto required_classes = [](const PassDecl& d) {
    std::vector<uint32_t> req;
    for (const SlotDecl& s : d.slots) {
      if (s.direction == SlotDirection::output || s.direction == SlotDirection::history) continue;
      if (s.direction == SlotDirection::input && s.optional) continue;
      req.push_back(accepted_classes(s.kind, s.usage));
    }
    return req;
  };
  std::vector<std::vector<uint32_t>> req(out.decls.size());
  std::vector<uint32_t> produces(out.decls.size(), 0);
  for (size_t i = 0; i < out.decls.size(); ++i) {
    req[i] = required_classes(*out.decls[i]);
    for (const SlotDecl& s : out.decls[i]->slots) {
      if (s.direction != SlotDirection::output) continue;
      ResourceDesc d;
      d.kind = s.kind;
      d.format = s.format;
      produces[i] |= 1u << class_of(d);
    }
  }
  uint32_t available = 0;
  std::vector<uint32_t> fitting;
  auto rebuild = [&] {
    fitting.clear();
    for (size_t i = 0; i < out.decls.size(); ++i) {
      bool ok = true;
      for (uint32_t c : req[i]) ok = ok && (c & available) != 0;
      if (ok) fitting.push_back(static_cast<uint32_t>(i));
    }
  };
  rebuild();
  // consume_unread: of four fitting decls, the one that reads more of the classes made
  // but not yet read (and makes fewer of them), so that what passes make gets read.
  std::array<uint32_t, kClassCount> unread{};
  auto unread_class_for = [&](const SlotDecl& s) {  // the first class the slot takes with some unread; kClassCount if none
    uint32_t c = 0;
    while (c < kClassCount && !((accepted_classes(s.kind, s.usage) & bit(Cls(c))) && unread[c] > 0)) ++c;
    return c;
  };
  auto reads = [](const SlotDecl& s) { return s.direction == SlotDirection::input || s.direction == SlotDirection::inout; };
  auto reads_unread = [&](uint32_t d) {
    int score = 0;
    for (const SlotDecl& s : out.decls[d]->slots) score += reads(s) && unread_class_for(s) < kClassCount;
    for (uint32_t c = 0; c < kClassCount; ++c) score -= (produces[d] & bit(Cls(c))) && unread[c] > 0;
    return score;
  };
  auto account = [&](uint32_t d) {
    for (const SlotDecl& s : out.decls[d]->slots) {
      if (!reads(s)) continue;
      if (const uint32_t c = unread_class_for(s); c < kClassCount) --unread[c];
    }
    for (uint32_t c = 0; c < kClassCount; ++c) unread[c] += (produces[d] & bit(Cls(c))) != 0;
  };
  std::vector<uint32_t> sequence(options.passes);
  for (uint32_t s = 0; s < options.passes; ++s) {
    uint32_t d = rng.pick(fitting);
    if (options.consume_unread) {
      for (int k = 0; k < 3; ++k) {
        const uint32_t other = rng.pick(fitting);
        if (reads_unread(other) > reads_unread(d)) d = other;
      }
      account(d);
    }
    sequence[s] = d;
    if ((available | produces[d]) != available) {
      available |= produces[d];
      rebuild();
    }
  }

  // Phase 2: add the passes in a shuffled order.
  GraphBuilder builder(output_size, scene);
  std::vector<uint32_t> add_order(options.passes);
  for (uint32_t s = 0; s < options.passes; ++s) add_order[s] = s;
  rng.shuffle(add_order);
  std::vector<uint32_t> pass_of(options.passes, kNone);
  for (uint32_t i = 0; i < options.passes; ++i) {
    const uint32_t s = add_order[i];
    const PassDecl& d = *out.decls[sequence[s]];
    pass_of[s] = builder.add_pass(d.name + "_" + std::to_string(i), d);
  }

  // Phase 3: wire along the hidden sequence. Besides the builder's own bookkeeping we
  // keep every ordering edge (producer -> reader, reader -> next modifier), so that a
  // read of an older version ("stale" read: the reader must run before the modifier
  // that the hidden sequence put first) is only made when it closes no cycle.
  Wiring wiring(rng, options);
  std::vector<uint32_t> latest;  // per resource: its latest version
  std::vector<uint32_t> cls;     // per resource: its class
  std::vector<std::vector<std::vector<uint32_t>>> readers;  // per resource, per version
  std::vector<std::vector<uint32_t>> preds(options.passes);  // per pass: passes that must run first
  std::vector<uint32_t> used;    // resources the current pass already uses
  std::vector<uint32_t> not_modifiable;  // per pass: `used`, and outputs kept as history (never modified)
  std::vector<uint32_t> with_history;
  std::vector<std::pair<uint32_t, Usage>> inputs_here;
  std::vector<uint32_t> stamp(options.passes, 0), stack;
  uint32_t tick = 0;
  auto writer_of = [&](uint32_t r, uint32_t v) { return builder.graph().resources[r].version_writers[v]; };
  // Whether `a` must run before `b` already (a is an ancestor of b); gives up (true) on huge searches.
  auto ancestor = [&](uint32_t a, uint32_t b) {
    ++tick;
    stack.assign(1, b);
    size_t visited = 0;
    while (!stack.empty()) {
      const uint32_t x = stack.back();
      stack.pop_back();
      if (x == a) return true;
      if (stamp[x] == tick) continue;
      stamp[x] = tick;
      if (++visited > 200000) return true;
      for (uint32_t y : preds[x]) stack.push_back(y);
    }
    return false;
  };
  auto read_version = [&](uint32_t p, uint16_t slot, uint32_t r, uint32_t v) {
    builder.read(p, slot, {r, v});
    if (v == latest[r]) wiring.mark_read(r);
    preds[p].push_back(writer_of(r, v));
    readers[r][v].push_back(p);
  };
  for (uint32_t s = 0; s < options.passes; ++s) {
    const uint32_t p = pass_of[s];
    const PassDecl& d = *out.decls[sequence[s]];
    used.clear();
    inputs_here.clear();
    // Inouts first, so inputs can stay off the resource being modified.
    for (size_t i = 0; i < d.slots.size(); ++i) {
      const SlotDecl& slot = d.slots[i];
      if (slot.direction != SlotDirection::inout) continue;
      not_modifiable = used;
      not_modifiable.insert(not_modifiable.end(), with_history.begin(), with_history.end());
      const uint32_t r = wiring.pick(accepted_classes(slot.kind, slot.usage), s, not_modifiable);
      if (r == kNone) continue;  // cannot happen for a fitting decl; stay safe
      const uint32_t v = latest[r];
      wiring.mark_read(r);
      preds[p].push_back(writer_of(r, v));
      for (uint32_t q : readers[r][v]) {
        if (q != p) preds[p].push_back(q);
      }
      const ResourceVersion nv = builder.modify(p, static_cast<uint16_t>(i), {r, v});
      latest[r] = nv.version;
      readers[r].emplace_back();
      wiring.touch(r, cls[r], s);
      used.push_back(r);
    }
    // At most one input per pass tries a stale read, after all other edges into the pass.
    int stale_slot = -1;
    for (size_t i = 0; i < d.slots.size(); ++i) {
      if (d.slots[i].direction == SlotDirection::input && rng.chance(options.stale_fraction)) stale_slot = int(i);
    }
    for (size_t i = 0; i < d.slots.size(); ++i) {
      const SlotDecl& slot = d.slots[i];
      if (slot.direction != SlotDirection::input || int(i) == stale_slot) continue;
      if (slot.optional && rng.chance(0.3)) continue;  // left unbound
      uint32_t r = kNone;
      // Now and then read a resource this pass already reads, when the layouts agree,
      // so that passes using one resource in two slots appear.
      if (!inputs_here.empty() && rng.chance(0.05)) {
        const auto& [other, other_usage] = inputs_here[rng.below(inputs_here.size())];
        const ResourceKind k = builder.graph().resources[other].desc.kind;
        if ((accepted_classes(slot.kind, slot.usage) & (1u << cls[other])) &&
            access_state(other_usage, d.kind, k).layout == access_state(slot.usage, d.kind, k).layout) {
          r = other;
        }
      }
      if (r == kNone) r = wiring.pick(accepted_classes(slot.kind, slot.usage), s, used);
      if (r == kNone) continue;  // no distinct resource left: leave the slot unbound
      read_version(p, static_cast<uint16_t>(i), r, latest[r]);
      used.push_back(r);
      inputs_here.emplace_back(r, slot.usage);
    }
    if (stale_slot >= 0 && !(d.slots[stale_slot].optional && rng.chance(0.3))) {
      const SlotDecl& slot = d.slots[stale_slot];
      const uint16_t si = static_cast<uint16_t>(stale_slot);
      const uint32_t r = wiring.pick(accepted_classes(slot.kind, slot.usage), s, used);
      if (r != kNone) {
        bool done = false;
        if (latest[r] > 0) {
          const uint32_t back = 1 + static_cast<uint32_t>(rng.below(std::min<uint32_t>(latest[r], 3)));
          const uint32_t v = latest[r] - back;
          const uint32_t modifier = writer_of(r, v + 1);
          if (!ancestor(modifier, p)) {
            read_version(p, si, r, v);
            preds[modifier].push_back(p);
            done = true;
          }
        }
        // Otherwise the latest version; safe, as nothing waits on this pass yet.
        if (!done) read_version(p, si, r, latest[r]);
        used.push_back(r);
      }
    }
    std::vector<ResourceVersion> made(d.slots.size());
    for (size_t i = 0; i < d.slots.size(); ++i) {
      const SlotDecl& slot = d.slots[i];
      if (slot.direction != SlotDirection::output) continue;
      const ResourceVersion v = builder.create(p, static_cast<uint16_t>(i), resolve_slot(d, slot, output_size, 0));
      made[i] = v;
      latest.push_back(0);
      readers.emplace_back(1);
      cls.push_back(class_of(builder.graph().resources[v.resource].desc));
      wiring.touch(v.resource, cls.back(), s);
    }
    for (size_t i = 0; i < d.slots.size(); ++i) {  // the previous frame's resource: no pass of this frame makes it
      const SlotDecl& slot = d.slots[i];
      if (slot.direction != SlotDirection::history) continue;
      const ResourceVersion followed = made[size_t(d.slot_index(slot.history_of))];
      builder.read_history(p, static_cast<uint16_t>(i), followed);
      with_history.push_back(followed.resource);
      latest.push_back(0);
      readers.emplace_back(1);
      cls.push_back(cls[followed.resource]);
    }
  }

  // Graph outputs: latest versions only, at least one.
  bool any = false;
  for (uint32_t r = 0; r < latest.size(); ++r) {
    if (builder.graph().resources[r].previous_of != kNone) continue;  // a history: not this frame's
    if (rng.chance(options.output_fraction)) {
      builder.mark_output({r, latest[r]});
      any = true;
    }
  }
  if (options.consume_unread) {  // what the frame's last passes (and any other pass no pass reads) make
    for (uint32_t r = 0; r < latest.size(); ++r) {
      if (!wiring.left_by_unfed_pass(r)) continue;
      builder.mark_output({r, latest[r]});
      any = true;
    }
  }
  if (!any && !latest.empty()) {
    uint32_t r = static_cast<uint32_t>(latest.size() - 1);
    if (builder.graph().resources[r].previous_of != kNone) r = builder.graph().resources[r].previous_of;
    builder.mark_output({r, latest[r]});
  }

  out.graph = builder.finish();
  return out;
}

// ---------------------------------------------------------------------------------------

GraphSketch::GraphSketch(Extent output_size, SceneFeatures scene) : builder_(output_size, scene) {}

uint32_t GraphSketch::pass(std::string name, PassKind kind, std::vector<SlotDecl> slots, SceneFeatures needs) {
  auto d = std::make_unique<PassDecl>();
  d->name = name;
  d->kind = kind;
  d->variants.push_back({"default", ""});
  d->slots = std::move(slots);
  d->needs = needs;
  const uint32_t id = builder_.add_pass(std::move(name), *d);
  decls_.push_back(std::move(d));
  return id;
}

uint16_t GraphSketch::slot_of(uint32_t pass, std::string_view slot) {
  const int i = builder_.graph().passes.at(pass).decl->slot_index(slot);
  if (i < 0) throw std::invalid_argument("GraphSketch: no slot '" + std::string(slot) + "'");
  return static_cast<uint16_t>(i);
}

ResourceVersion GraphSketch::out(uint32_t pass, std::string_view slot) {
  const uint16_t i = slot_of(pass, slot);
  const PassDecl& d = *builder_.graph().passes.at(pass).decl;
  return builder_.create(pass, i, resolve_slot(d, d.slots[i], builder_.graph().output_size, 64));
}

void GraphSketch::in(uint32_t pass, std::string_view slot, ResourceVersion what) {
  builder_.read(pass, slot_of(pass, slot), what);
}

ResourceVersion GraphSketch::inout(uint32_t pass, std::string_view slot, ResourceVersion what) {
  return builder_.modify(pass, slot_of(pass, slot), what);
}

void GraphSketch::output(ResourceVersion what) { builder_.mark_output(what); }

RandomGraph GraphSketch::finish() {
  RandomGraph g;
  g.decls = std::move(decls_);
  g.graph = builder_.finish();
  return g;
}

SlotDecl out_slot(std::string name, ResourceKind kind, Usage usage, Format format, SizeSpec size, bool persistent) {
  SlotDecl s = slot_out(std::move(name), kind, usage, format, std::move(size), "");
  s.persistent = persistent;
  return s;
}

SlotDecl in_slot(std::string name, ResourceKind kind, Usage usage, bool optional) {
  SlotDecl s = slot_in(std::move(name), kind, usage, "");
  s.optional = optional;
  return s;
}

SlotDecl inout_slot(std::string name, ResourceKind kind, Usage usage) {
  return slot_inout(std::move(name), kind, usage, "");
}

std::string graph_text(const Graph& graph) {
  std::ostringstream os;
  os << "graph: " << graph.passes.size() << " passes, " << graph.resources.size() << " resources, scene=0x"
     << std::hex << graph.scene << std::dec << "\n";
  for (size_t p = 0; p < graph.passes.size(); ++p) {
    const GraphPass& pass = graph.passes[p];
    os << "  pass " << p << " '" << pass.name << "' " << pass_kind_name(pass.kind);
    if (pass.needs) os << " needs=0x" << std::hex << pass.needs << std::dec;
    os << "\n";
    for (const ResourceUse& u : pass.uses) {
      const char* dir = u.direction == SlotDirection::input     ? "in"
                        : u.direction == SlotDirection::inout   ? "inout"
                        : u.direction == SlotDirection::history ? "history"
                                                                : "out";
      os << "    " << dir << (u.optional ? "?" : "") << " " << usage_name(u.usage) << " r" << u.resource << "."
         << u.version;
      if (u.resource < graph.resources.size()) os << " (" << graph.resources[u.resource].desc.name << ")";
      os << "\n";
    }
  }
  for (size_t r = 0; r < graph.resources.size(); ++r) {
    const GraphResource& res = graph.resources[r];
    os << "  resource " << r << " '" << res.desc.name << "' " << kind_name(res.desc.kind) << " "
       << format_info(res.desc.format).name << " " << content_bytes(res.desc) << "B"
       << (res.desc.persistent ? " persistent" : "") << " writers:";
    for (uint32_t w : res.version_writers) os << " " << w;
    os << "\n";
  }
  os << "  outputs:";
  for (const ResourceVersion& o : graph.outputs) os << " r" << o.resource << "." << o.version;
  os << "\n";
  return os.str();
}

}  // namespace volgraph::test
