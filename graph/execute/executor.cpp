#include "graph/execute/executor.h"

#include <chrono>
#include <cstring>

#include "graph/rhi/device_error.h"

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

}  // namespace

Executor::Executor(rhi::Device& device, const Graph& graph, const Scene* scene, const CompileOptions& options)
    : device_(device), graph_(graph), scene_(scene), resources_(device.create_graph_resources(graph)) {
  plan_ = compile(graph, options, resources_->requirements());
  for (const PlannedPass& p : plan_.order) {
    const PassDecl& decl = *graph.passes[p.pass].decl;
    if (!decl.make_execution) {
      throw DeviceError(DeviceError::Kind::unsupported, "pass \"" + graph.passes[p.pass].name + "\" (" + decl.name +
                                                            ") has no GPU implementation yet");
    }
    executions_.push_back(decl.make_execution());
  }
  resources_->bind(plan_);
  if (device.has_timestamps() && !plan_.order.empty()) {
    queries_ = device.create_timestamp_queries("pass times", uint32_t(2 * plan_.order.size()));
  }
}

Executor::~Executor() = default;

// The plan's transitions before a pass. On the first frame, persistent resources have
// no previous frame: their first transition starts from undefined contents.
std::vector<rhi::ResourceBarrier> Executor::barriers_before(uint32_t position) const {
  std::vector<rhi::ResourceBarrier> out;
  const PlannedPass& p = plan_.order[position];
  for (uint32_t i = p.barrier_begin; i < p.barrier_begin + p.barrier_count; ++i) {
    const Barrier& b = plan_.barriers[i];
    rhi::ResourceBarrier rb{{}, {}, b.from, b.to};
    if (b.resource != kNone) {
      const ResourceDesc& d = graph_.resources[b.resource].desc;
      if (d.kind == ResourceKind::buffer) rb.buffer = resources_->buffer(b.resource);
      else rb.texture = resources_->texture(b.resource);
      if (frame_ == 0 && d.persistent && plan_.lifetimes[b.resource].first == position) {
        rb.from = {stage::none, access::none, d.kind == ResourceKind::buffer ? Layout::none : Layout::undefined};
      }
    }
    out.push_back(rb);
  }
  return out;
}

void Executor::run_frame() {
  auto encoder = device_.create_command_encoder("frame " + std::to_string(frame_));
  std::vector<double> cpu_ms(plan_.order.size());
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const GraphPass& pass = graph_.passes[plan_.order[pos].pass];
    encoder->push_debug_group(pass.name + " (" + pass.decl->name + ")");
    const std::vector<rhi::ResourceBarrier> barriers = barriers_before(pos);
    if (!barriers.empty()) encoder->barrier(barriers);
    if (queries_) encoder->write_timestamp(queries_, 2 * pos);
    const auto start = std::chrono::steady_clock::now();
    PassContext context(device_, *encoder, graph_, plan_.order[pos].pass, *resources_, scene_);
    executions_[pos]->record(context);
    cpu_ms[pos] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (queries_) encoder->write_timestamp(queries_, 2 * pos + 1);
    encoder->pop_debug_group();
  }
  const auto submitted = std::chrono::steady_clock::now();
  device_.submit(std::move(encoder));
  frame_wall_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - submitted).count();
  timings_.clear();
  const std::vector<double> ns =
      queries_ ? device_.read_timestamps(queries_, 0, uint32_t(2 * plan_.order.size())) : std::vector<double>{};
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const GraphPass& p = graph_.passes[plan_.order[pos].pass];
    const double gpu = ns.empty() ? 0.0 : (ns[2 * pos + 1] - ns[2 * pos]) * 1e-6;
    timings_.push_back({p.name, p.decl->name, gpu, cpu_ms[pos]});
  }
  ++frame_;
}

// The state the resource's last use in the frame left it in.
AccessState Executor::last_state(uint32_t r) const {
  AccessState last{};
  for (uint32_t pos = 0; pos < plan_.order.size(); ++pos) {
    const GraphPass& p = graph_.passes[plan_.order[pos].pass];
    for (const ResourceUse& u : p.uses) {
      if (u.resource == r) last = access_state(u.usage, p.kind, graph_.resources[r].desc.kind);
    }
  }
  return last;
}

Texels Executor::read_texture(uint32_t r) {
  const ResourceDesc& d = graph_.resources[r].desc;
  const bool mono = d.format == Format::r32_float || d.format == Format::d32_float;
  if (d.kind != ResourceKind::texture2d ||
      (d.format != Format::rgba32_float && d.format != Format::rgba16_float && !mono)) {
    throw DeviceError(DeviceError::Kind::unsupported,
                      d.name + " is a " + std::string(kind_name(d.kind)) + " of " + std::string(format_info(d.format).name) +
                          "; reading back takes 2D rgba32_float, rgba16_float, r32_float or d32_float textures");
  }
  if (!resources_->texture(r)) throw DeviceError(DeviceError::Kind::other, d.name + " was not used in the last frame");
  const uint32_t texel_bytes = format_info(d.format).bytes_per_texel;
  const rhi::BufferId readback = device_.create_buffer(
      {d.name + " read-back", uint64_t(d.extent.width) * d.extent.height * texel_bytes, rhi::buffer_usage::copy_dst});
  auto encoder = device_.create_command_encoder("read " + d.name);
  const rhi::ResourceBarrier to_copy{resources_->texture(r), {}, last_state(r),
                                     access_state(Usage::copy_src, PassKind::transfer, d.kind)};
  encoder->barrier({&to_copy, 1});
  encoder->copy_texture_to_buffer(resources_->texture(r), readback, 0);
  device_.submit(std::move(encoder));
  const std::vector<std::byte> raw = device_.read_buffer(readback);
  device_.destroy(readback);
  const size_t texels = size_t(d.extent.width) * d.extent.height;
  Texels out{d.extent.width, d.extent.height, std::vector<float>(texels * 4, 1.0f)};
  for (size_t t = 0; t < texels; ++t) {
    if (mono) {
      float v;
      std::memcpy(&v, raw.data() + 4 * t, 4);
      out.rgba[4 * t] = out.rgba[4 * t + 1] = out.rgba[4 * t + 2] = v;
    } else if (d.format == Format::rgba32_float) {
      std::memcpy(&out.rgba[4 * t], raw.data() + 16 * t, 16);
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

std::vector<std::byte> Executor::read_buffer(uint32_t r) {
  const ResourceDesc& d = graph_.resources[r].desc;
  if (d.kind != ResourceKind::buffer || !resources_->buffer(r)) {
    throw DeviceError(DeviceError::Kind::other, d.name + " is not a buffer used in the last frame");
  }
  const rhi::BufferId readback = device_.create_buffer({d.name + " read-back", d.buffer_bytes, rhi::buffer_usage::copy_dst});
  auto encoder = device_.create_command_encoder("read " + d.name);
  const rhi::ResourceBarrier to_copy{{}, resources_->buffer(r), last_state(r),
                                     access_state(Usage::copy_src, PassKind::transfer, d.kind)};
  encoder->barrier({&to_copy, 1});
  encoder->copy_buffer_to_buffer(resources_->buffer(r), readback, d.buffer_bytes);
  device_.submit(std::move(encoder));
  std::vector<std::byte> bytes = device_.read_buffer(readback);
  device_.destroy(readback);
  return bytes;
}

}  // namespace volgraph
