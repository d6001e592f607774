#include "graph/execute/executor.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include "graph/execute/cache_key.h"
#include "graph/rhi/device_error.h"
#include "graph/scene/scene.h"

namespace volgraph {
namespace {

float half_to_float(uint16_t h) {
  const uint32_t sign = uint32_t(h >> 15) << 31, exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
  uint32_t bits;
  if (exponent == 0) {
    if (mantissa == 0) {
      bits = sign;
    } else {  // subnormal: renormalise
      uint32_t e = 113, m = mantissa;
      while (!(m & 0x400)) {
        m <<= 1;
        --e;
      }
      bits = sign | (e << 23) | ((m & 0x3ff) << 13);
    }
  } else if (exponent == 31) {
    bits = sign | 0x7f800000u | (mantissa << 13);
  } else {
    bits = sign | ((exponent + 112) << 23) | (mantissa << 13);
  }
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

// The texture formats read back as texels (2D, or 3D slice by slice).
bool readable_as_texels(const ResourceDesc& d) {
  const bool mono = d.format == Format::r32_float || d.format == Format::d32_float;
  return d.kind != ResourceKind::buffer &&
         (d.format == Format::rgba32_float || d.format == Format::rgba16_float || d.format == Format::rgba8_unorm || mono);
}

DeviceError not_texels(const ResourceDesc& d) {
  return DeviceError(DeviceError::Kind::unsupported,
                     d.name + " is a " + std::string(kind_name(d.kind)) + " of " + std::string(format_info(d.format).name) +
                         "; reading back takes rgba32_float, rgba16_float, rgba8_unorm, r32_float or d32_float textures");
}

// A volume's slices, a cube's faces (+x, −x, +y, −y, +z, −z), else 1.
uint32_t slices(const ResourceDesc& d) { return d.kind == ResourceKind::texture3d ? std::max(1u, d.extent.depth) : array_layers(d.kind); }

uint64_t readback_bytes(const ResourceDesc& d) {
  if (d.kind == ResourceKind::buffer) return d.buffer_bytes;
  return uint64_t(d.extent.width) * d.extent.height * slices(d) * format_info(d.format).bytes_per_texel;
}

// A texture's read-back bytes (rows tightly packed, slice after slice) as RGBA floats;
// a one-channel format is copied to RGB, alpha 1.
Texels texels_of(const ResourceDesc& d, const std::vector<std::byte>& raw) {
  const bool mono = d.format == Format::r32_float || d.format == Format::d32_float;
  const size_t texels = size_t(d.extent.width) * d.extent.height * slices(d);
  Texels out{d.extent.width, d.extent.height, std::vector<float>(texels * 4, 1.0f), slices(d)};
  for (size_t t = 0; t < texels; ++t) {
    if (mono) {
      float v;
      std::memcpy(&v, raw.data() + 4 * t, 4);
      out.rgba[4 * t] = out.rgba[4 * t + 1] = out.rgba[4 * t + 2] = v;
    } else if (d.format == Format::rgba32_float) {
      std::memcpy(&out.rgba[4 * t], raw.data() + 16 * t, 16);
    } else if (d.format == Format::rgba8_unorm) {
      for (size_t c = 0; c < 4; ++c) out.rgba[4 * t + c] = float(uint8_t(raw[4 * t + c])) / 255.0f;
    } else {
      for (size_t c = 0; c < 4; ++c) {
        uint16_t h;
        std::memcpy(&h, raw.data() + 8 * t + 2 * c, 2);
        out.rgba[4 * t + c] = half_to_float(h);
      }
    }
  }
  return out;
}

// The plan's tables are indexed by the graph's passes and resources, every pass's
// barriers lie inside the barrier list and name the graph's resources.
bool plan_fits(const Graph& graph, const Plan& plan) {
  if (plan.position.size() != graph.passes.size() || plan.lifetimes.size() != graph.resources.size() ||
      plan.placements.size() != graph.resources.size()) {
    return false;
  }
  for (const PlannedPass& p : plan.order) {
    if (p.pass >= graph.passes.size() || uint64_t(p.barrier_begin) + p.barrier_count > plan.barriers.size()) return false;
  }
  for (const std::vector<Barrier>* list : {&plan.barriers, &plan.initial_barriers}) {
    for (const Barrier& b : *list) {
      if (b.resource != kNone && b.resource >= graph.resources.size()) return false;
    }
  }
  return true;
}

}  // namespace

Executor::Executor(rhi::Device& device, const Graph& graph, const Scene* scene, const CompileOptions& options)
    : device_(device), graph_(graph), scene_(scene), resources_(device.create_graph_resources(graph)) {
  plan_ = compile(graph, options, resources_->requirements());
  prepare();
}

Executor::Executor(rhi::Device& device, const Graph& graph, const Scene* scene,
                   std::unique_ptr<rhi::GraphResourceSet> resources, Plan plan)
    : device_(device), graph_(graph), scene_(scene), resources_(std::move(resources)), plan_(std::move(plan)) {
  prepare();
}

Plan Executor::compile_for(rhi::Device& device, const Graph& graph, const CompileOptions& options) {
  return compile(graph, options, device.create_graph_resources(graph)->requirements());
}

std::unique_ptr<Executor> Executor::for_plan(rhi::Device& device, const Graph& graph, const Scene* scene, Plan plan) {
  if (!plan_fits(graph, plan)) throw std::invalid_argument("the plan given to the executor is not this graph's plan");
  return std::unique_ptr<Executor>(new Executor(device, graph, scene, device.create_graph_resources(graph), std::move(plan)));
}

// Each pass's execution, the plan's memory bound, then every execution's setup.
void Executor::prepare() {
  for (const PlannedPass& p : plan_.order) {
    const GraphPass& pass = graph_.passes[p.pass];
    const PassDecl& decl = *pass.decl;
    if (!decl.make_execution) {
      throw DeviceError(DeviceError::Kind::unsupported, "pass \"" + pass.name + "\" (" + decl.name + ") has no GPU implementation yet");
    }
    executions_.push_back(shared_execution(pass));
  }
  resources_->bind(plan_);
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const bool first_of_its_pass = std::find(executions_.begin(), executions_.begin() + pos, executions_[pos]) == executions_.begin() + pos;
    if (!first_of_its_pass) continue;  // a later step of a pass set up already
    PassSetup setup(device_, graph_, plan_.order[pos].pass, *resources_, scene_);
    setup.collect_notes(&plan_.setup_notes);
    executions_[pos]->setup(setup);
  }
  pass_keys_.assign(plan_.order.size(), 0);
  content_keys_.assign(graph_.resources.size(), 0);
}

// The pass's execution: a new one, or for a step of a pass made of steps the one its
// earlier steps share.
std::shared_ptr<PassExecution> Executor::shared_execution(const GraphPass& pass) {
  if (pass.group != kNone) {
    for (uint32_t pos = 0; pos < executions_.size(); ++pos) {
      if (graph_.passes[plan_.order[pos].pass].group == pass.group) return executions_[pos];
    }
  }
  return std::shared_ptr<PassExecution>(pass.decl->make_execution());
}

// Whether this frame writes time stamps; their queries are made for the first timed frame.
bool Executor::timing_frame() {
  if (!gpu_timing_ || !device_.has_timestamps() || plan_.order.empty()) return false;
  if (!queries_) queries_ = device_.create_timestamp_queries("pass times", uint32_t(2 * plan_.order.size()));
  return true;
}

Executor::~Executor() = default;

// The plan's transitions before a pass.
std::vector<rhi::ResourceBarrier> Executor::barriers_before(uint32_t position) const {
  const PlannedPass& p = plan_.order[position];
  return device_barriers({plan_.barriers.data() + p.barrier_begin, p.barrier_count});
}

std::vector<rhi::ResourceBarrier> Executor::device_barriers(std::span<const Barrier> barriers) const {
  std::vector<rhi::ResourceBarrier> out;
  for (const Barrier& b : barriers) {
    if (b.resource == kNone) out.push_back({{}, {}, b.from, b.to});
    else out.push_back(barrier_of(b.resource, b.from, b.to));
  }
  return out;
}

// Every frame after the first, each history pair's two objects trade places: the
// output's object of the last frame becomes its history, and the history's is written.
void Executor::swap_history_pairs() {
  for (uint32_t r = 0; r < graph_.resources.size(); ++r) {
    const uint32_t previous = graph_.resources[r].previous;
    if (previous != kNone && plan_.lifetimes[r].first != kNone) resources_->swap(r, previous);
  }
}

void Executor::run_frame() { run_frame_and_read({}); }

std::vector<Readback> Executor::run_frame_and_read(std::span<const uint32_t> resources) {
  for (const uint32_t r : resources) check_readable(r);
  const bool timed = timing_frame();
  if (frame_ > 0) swap_history_pairs();
  auto encoder = device_.create_command_encoder("frame " + std::to_string(frame_));
  if (frame_ == 0 && !plan_.initial_barriers.empty()) encoder->barrier(device_barriers(plan_.initial_barriers));
  std::vector<double> cpu_ms(plan_.order.size());
  std::vector<uint8_t> skipped(plan_.order.size(), 0);
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const GraphPass& pass = graph_.passes[plan_.order[pos].pass];
    encoder->push_debug_group(pass.name + " (" + pass.decl->name + ")");
    // The plan's barriers are recorded even for a pass the cache skips: they move its
    // outputs through the states the plan expects, keeping their contents.
    const std::vector<rhi::ResourceBarrier> barriers = barriers_before(pos);
    if (!barriers.empty()) encoder->barrier(barriers);
    if (timed) encoder->write_timestamp(queries_, 2 * pos);
    const auto start = std::chrono::steady_clock::now();
    skipped[pos] = update_cache_key(pos);
    if (!skipped[pos]) {
      PassContext context(device_, *encoder, graph_, plan_.order[pos].pass, *resources_, scene_);
      context.frame = frame_;
      context.history_valid = frame_ > 0;
      executions_[pos]->record(context);
    }
    cpu_ms[pos] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (timed) encoder->write_timestamp(queries_, 2 * pos + 1);
    encoder->pop_debug_group();
  }
  const PendingReadback pending = record_readback(*encoder, resources);
  const auto submitted = std::chrono::steady_clock::now();
  device_.submit(std::move(encoder));
  frame_wall_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - submitted).count();
  timings_.clear();
  const std::vector<double> ns =
      timed ? device_.read_timestamps(queries_, 0, uint32_t(2 * plan_.order.size())) : std::vector<double>{};
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const GraphPass& p = graph_.passes[plan_.order[pos].pass];
    const double gpu = ns.empty() ? 0.0 : (ns[2 * pos + 1] - ns[2 * pos]) * 1e-6;
    timings_.push_back({p.name, p.decl->name, gpu, cpu_ms[pos], bool(skipped[pos])});
  }
  ++frame_;
  return collect(pending, resources);
}

// The pass's cache key this frame (cache_key.h), kept with the resources it writes;
// true when the pass is cached, has run before and its key has not changed: it is
// skipped, its persistent outputs keeping what it wrote.
bool Executor::update_cache_key(uint32_t pos) {
  const GraphPass& pass = graph_.passes[plan_.order[pos].pass];
  CacheKeyInputs in;
  in.pass = &pass;
  in.frame = frame_;
  in.scene_hash = scene_ ? scene_->hash(pass.decl->reads_scene) : 0;
  for (const ResourceUse& u : pass.uses) {
    if (u.direction != SlotDirection::output) in.input_keys.push_back(content_keys_[u.resource]);  // what it reads of others (or of last frame)
  }
  const uint64_t key = pass_cache_key(in);
  const bool skip = pass.decl->cached && frame_ > 0 && key == pass_keys_[pos];
  pass_keys_[pos] = key;
  for (const ResourceUse& u : pass.uses) {
    if (u.direction == SlotDirection::output || u.direction == SlotDirection::inout) content_keys_[u.resource] = key;
  }
  return skip;
}

rhi::ResourceBarrier Executor::barrier_of(uint32_t r, const AccessState& from, const AccessState& to) const {
  if (graph_.resources[r].desc.kind == ResourceKind::buffer) return {{}, resources_->buffer(r), from, to};
  return {resources_->texture(r), {}, from, to};
}

// The state the resource's last use in the frame left it in (the plan says).
AccessState Executor::last_state(uint32_t r) const { return r < plan_.final_states.size() ? plan_.final_states[r] : AccessState{}; }

void Executor::check_readable(uint32_t r) const {
  const ResourceDesc& d = graph_.resources[r].desc;
  const bool buffer = d.kind == ResourceKind::buffer;
  if (!buffer && !readable_as_texels(d)) throw not_texels(d);
  if (buffer ? !resources_->buffer(r) : !resources_->texture(r)) {
    throw DeviceError(DeviceError::Kind::other, d.name + " was not used in the last frame");
  }
}

// Once per resource, from the state the frame left it in to copy source (`to_copy`),
// or back (persistent resources only) to the state the next frame's plan expects.
std::vector<rhi::ResourceBarrier> Executor::copy_source_transitions(std::span<const uint32_t> resources, bool to_copy) const {
  std::vector<rhi::ResourceBarrier> out;
  for (size_t i = 0; i < resources.size(); ++i) {
    const uint32_t r = resources[i];
    if (std::find(resources.begin(), resources.begin() + i, r) != resources.begin() + i) continue;
    const AccessState copy_source = access_state(Usage::copy_src, PassKind::transfer, graph_.resources[r].desc.kind);
    // Back again: a persistent resource to where the next frame starts it, a transient one
    // to its last state (where the next read-back of this frame's result expects it).
    if (to_copy) out.push_back(barrier_of(r, last_state(r), copy_source));
    else out.push_back(barrier_of(r, copy_source, graph_.resources[r].desc.persistent ? next_frame_start(r) : last_state(r)));
  }
  return out;
}

// The state persistent resource r's object must be in when the next frame starts: as
// the plan's initial barriers leave the resource it plays then (a history pair's object
// plays the other role), or for buffers (no layout), as its last use left it.
AccessState Executor::next_frame_start(uint32_t r) const {
  const GraphResource& res = graph_.resources[r];
  const uint32_t role = res.previous != kNone ? res.previous : res.previous_of != kNone ? res.previous_of : r;
  for (const Barrier& b : plan_.initial_barriers) {
    if (b.resource == role) return b.to;
  }
  return last_state(r);
}

// Every resource copied into one read-back buffer, each at a 16-byte aligned offset
// (texel-size aligned for texture copies).
Executor::PendingReadback Executor::record_readback(rhi::CommandEncoder& encoder, std::span<const uint32_t> resources) {
  PendingReadback pending;
  if (resources.empty()) return pending;
  uint64_t total = 0;
  for (const uint32_t r : resources) {
    pending.offsets.push_back(total);
    total += (readback_bytes(graph_.resources[r].desc) + 15) / 16 * 16;
  }
  pending.buffer = device_.create_buffer({"read-back", total, rhi::buffer_usage::copy_dst});
  encoder.barrier(copy_source_transitions(resources, true));
  for (size_t i = 0; i < resources.size(); ++i) {
    const uint32_t r = resources[i];
    if (graph_.resources[r].desc.kind == ResourceKind::buffer) {
      encoder.copy_buffer_to_buffer(resources_->buffer(r), pending.buffer, graph_.resources[r].desc.buffer_bytes,
                                    pending.offsets[i]);
    } else {
      encoder.copy_texture_to_buffer(resources_->texture(r), pending.buffer, pending.offsets[i]);
    }
  }
  const std::vector<rhi::ResourceBarrier> back = copy_source_transitions(resources, false);
  if (!back.empty()) encoder.barrier(back);
  return pending;
}

std::vector<Readback> Executor::collect(const PendingReadback& pending, std::span<const uint32_t> resources) {
  if (resources.empty()) return {};
  const std::vector<std::byte> raw = device_.read_buffer(pending.buffer);
  device_.destroy(pending.buffer);
  std::vector<Readback> out;
  for (size_t i = 0; i < resources.size(); ++i) {
    const ResourceDesc& d = graph_.resources[resources[i]].desc;
    const auto begin = raw.begin() + std::ptrdiff_t(pending.offsets[i]);
    std::vector<std::byte> bytes(begin, begin + std::ptrdiff_t(readback_bytes(d)));
    if (d.kind == ResourceKind::buffer) out.push_back({{}, std::move(bytes)});
    else out.push_back({texels_of(d, bytes), {}});
  }
  return out;
}

std::vector<Readback> Executor::read_resources(std::span<const uint32_t> resources) {
  if (resources.empty()) return {};
  for (const uint32_t r : resources) check_readable(r);
  auto encoder = device_.create_command_encoder("read back");
  const PendingReadback pending = record_readback(*encoder, resources);
  device_.submit(std::move(encoder));
  return collect(pending, resources);
}

Texels Executor::read_texture(uint32_t r) {
  if (!readable_as_texels(graph_.resources[r].desc)) throw not_texels(graph_.resources[r].desc);
  return std::move(read_resources({&r, 1}).front().texels);
}

Texels Executor::read_texture_level(uint32_t r, uint32_t level) {
  const ResourceDesc& d = graph_.resources[r].desc;
  if (!readable_as_texels(d)) throw not_texels(d);
  if (level >= d.mip_levels) throw DeviceError(DeviceError::Kind::other, d.name + " has no mip level " + std::to_string(level));
  check_readable(r);
  ResourceDesc one = d;  // the level as a texture of its own
  one.extent = {std::max(1u, d.extent.width >> level), std::max(1u, d.extent.height >> level), std::max(1u, d.extent.depth >> level)};
  one.mip_levels = 1;
  const rhi::BufferId buffer = device_.create_buffer({"read-back level", (readback_bytes(one) + 15) / 16 * 16, rhi::buffer_usage::copy_dst});
  auto encoder = device_.create_command_encoder("read back a level");
  encoder->barrier(copy_source_transitions({&r, 1}, true));
  encoder->copy_texture_to_buffer(resources_->texture(r), buffer, 0, level);
  const std::vector<rhi::ResourceBarrier> back = copy_source_transitions({&r, 1}, false);
  if (!back.empty()) encoder->barrier(back);
  device_.submit(std::move(encoder));
  std::vector<std::byte> bytes = device_.read_buffer(buffer);
  device_.destroy(buffer);
  bytes.resize(readback_bytes(one));
  return texels_of(one, bytes);
}

std::vector<std::byte> Executor::read_buffer(uint32_t r) {
  const ResourceDesc& d = graph_.resources[r].desc;
  if (d.kind != ResourceKind::buffer) throw DeviceError(DeviceError::Kind::other, d.name + " is not a buffer");
  return std::move(read_resources({&r, 1}).front().bytes);
}

}  // namespace volgraph
