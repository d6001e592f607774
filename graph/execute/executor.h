// Runs a graph's compiled plan on a device: the plan's memory through the device's
// graph resources, the plan's barriers before each pass, each pass's execution, and a
// GPU time stamp around every pass.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/plan.h"
#include "graph/rhi/graph_resource_set.h"
#include "graph/rhi/rhi.h"

namespace volgraph {

struct PassTiming {
  std::string pass;
  std::string type;
  double gpu_ms = 0;  // from time stamps
  double cpu_ms = 0;  // recording on the CPU
  bool cached = false;  // skipped: its cache key had not changed (PassDecl::cached)
};

struct Texels {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;  // row 0 at the top; a 3D texture's slices one after another
  uint32_t depth = 1;       // slices
};

// One resource read back: a texture's texels or a buffer's bytes.
struct Readback {
  Texels texels;
  std::vector<std::byte> bytes;
};

class Executor {
 public:
  // Compiles with the device's memory requirements. Throws DeviceError (unsupported)
  // naming the first pass that must run and has no GPU implementation yet. Passes read
  // `scene` every frame: a caller may change it between frames (move the camera) as
  // long as it outlives the executor.
  Executor(rhi::Device& device, const Graph& graph, const Scene* scene, const CompileOptions& options);
  ~Executor();

  // The plan the constructor would run: compiled with the device's memory
  // requirements, for callers that inspect or edit it first.
  static Plan compile_for(rhi::Device& device, const Graph& graph, const CompileOptions& options);
  // Runs the given plan as it is instead of compiling one: a plan edited to debug
  // synchronisation or memory (barriers dropped, placements moved) runs exactly as
  // edited. It must be this graph's plan for this device (compile_for), edits aside;
  // throws std::invalid_argument when its tables do not fit the graph.
  static std::unique_ptr<Executor> for_plan(rhi::Device& device, const Graph& graph, const Scene* scene, Plan plan);

  const Plan& plan() const { return plan_; }
  void run_frame();
  // Runs one frame and reads `resources` back (as read_resources) at its end, in the
  // same submission: one wait on the device instead of two. frame_wall_ms then
  // includes the copies.
  std::vector<Readback> run_frame_and_read(std::span<const uint32_t> resources);
  const std::vector<PassTiming>& timings() const { return timings_; }
  // GPU time stamps around every pass: on by default (when the device has them). Off,
  // frames record none and cost less (a frame as it runs unprofiled); gpu_ms stays 0.
  void set_gpu_timing(bool on) { gpu_timing_ = on; }
  double frame_wall_ms() const { return frame_wall_ms_; }  // submit to completion, last frame
  // Graph output `index` (a 2D or 3D texture: rgba32/16 float, r32 float or d32 float;
  // one channel is copied to RGB) after the last frame.
  Texels read_output(size_t index) { return read_texture(graph_.outputs.at(index).resource); }
  Texels read_texture(uint32_t resource);
  // One level of a texture's mip chain (ResourceDesc::mip_levels), as read_texture reads level 0.
  Texels read_texture_level(uint32_t resource, uint32_t level);
  std::vector<std::byte> read_buffer(uint32_t resource);
  // Several resources (2D textures as read_texture takes, buffers) after the last
  // frame, in one submission rather than one wait on the device each.
  std::vector<Readback> read_resources(std::span<const uint32_t> resources);

 private:
  // Read-back copies recorded, not yet submitted: where each resource lands.
  struct PendingReadback {
    rhi::BufferId buffer;
    std::vector<uint64_t> offsets;
  };

  Executor(rhi::Device& device, const Graph& graph, const Scene* scene, std::unique_ptr<rhi::GraphResourceSet> resources,
           Plan plan);
  void prepare();
  bool timing_frame();
  std::vector<rhi::ResourceBarrier> barriers_before(uint32_t position) const;
  bool update_cache_key(uint32_t position);
  std::shared_ptr<PassExecution> shared_execution(const GraphPass& pass);
  std::vector<rhi::ResourceBarrier> device_barriers(std::span<const Barrier> barriers) const;
  void swap_history_pairs();
  rhi::ResourceBarrier barrier_of(uint32_t resource, const AccessState& from, const AccessState& to) const;
  std::vector<rhi::ResourceBarrier> copy_source_transitions(std::span<const uint32_t> resources, bool to_copy) const;
  void check_readable(uint32_t resource) const;
  PendingReadback record_readback(rhi::CommandEncoder& encoder, std::span<const uint32_t> resources);
  std::vector<Readback> collect(const PendingReadback& pending, std::span<const uint32_t> resources);
  AccessState last_state(uint32_t resource) const;
  AccessState next_frame_start(uint32_t resource) const;

  rhi::Device& device_;
  const Graph& graph_;
  const Scene* scene_;
  std::unique_ptr<rhi::GraphResourceSet> resources_;
  Plan plan_;
  std::vector<std::shared_ptr<PassExecution>> executions_;  // per plan position (a pass's steps share one)
  rhi::QuerySetId queries_;
  bool gpu_timing_ = true;
  std::vector<PassTiming> timings_;
  uint64_t frame_ = 0;
  std::vector<uint64_t> pass_keys_;     // per plan position: its cache key last frame
  std::vector<uint64_t> content_keys_;  // per resource: the key of the pass that last wrote it
  double frame_wall_ms_ = 0;
};

}  // namespace volgraph
