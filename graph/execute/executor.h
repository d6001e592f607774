// Runs a graph's compiled plan on a device: the plan's memory through the device's
// graph resources, the plan's barriers before each pass, each pass's execution, and a
// GPU time stamp around every pass.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/plan.h"
#include "graph/rhi/rhi.h"

namespace volgraph {

struct PassTiming {
  std::string pass;
  std::string type;
  double gpu_ms = 0;  // from time stamps
  double cpu_ms = 0;  // recording on the CPU
};

struct Texels {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;  // row 0 at the top
};

class Executor {
 public:
  // Compiles with the device's memory requirements. Throws DeviceError (unsupported)
  // naming the first pass that must run and has no GPU implementation yet.
  Executor(rhi::Device& device, const Graph& graph, const Scene* scene, const CompileOptions& options);
  ~Executor();

  const Plan& plan() const { return plan_; }
  void run_frame();
  const std::vector<PassTiming>& timings() const { return timings_; }
  double frame_wall_ms() const { return frame_wall_ms_; }  // submit to completion, last frame
  // Graph output `index` (a 2D texture: rgba32/16 float, r32 float or d32 float; one
  // channel is copied to RGB) after the last frame.
  Texels read_output(size_t index) { return read_texture(graph_.outputs.at(index).resource); }
  Texels read_texture(uint32_t resource);
  std::vector<std::byte> read_buffer(uint32_t resource);

 private:
  std::vector<rhi::ResourceBarrier> barriers_before(uint32_t position) const;
  AccessState last_state(uint32_t resource) const;

  rhi::Device& device_;
  const Graph& graph_;
  const Scene* scene_;
  std::unique_ptr<rhi::GraphResourceSet> resources_;
  Plan plan_;
  std::vector<std::unique_ptr<PassExecution>> executions_;  // per plan position
  rhi::QuerySetId queries_;
  std::vector<PassTiming> timings_;
  uint64_t frame_ = 0;
  double frame_wall_ms_ = 0;
};

}  // namespace volgraph
