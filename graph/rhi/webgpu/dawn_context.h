// The Dawn instance, adapter, device and queue volgraph renders with on WebGPU (Dawn's
// Vulkan backend on lavapipe here), and what the device reports back: every uncaptured
// error (validation, out of memory, internal) is collected as a message — tests fail on
// any, the command line stops at the first — and a loss of the device is remembered so
// the next submission reports it (as out of memory when memory was what ran out). Written against <webgpu/webgpu_cpp.h> only.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <webgpu/webgpu_cpp.h>

#include "graph/rhi/device_error.h"
#include "graph/rhi/rhi.h"

namespace volgraph::webgpu {

struct DawnOptions {
  // On: Dawn's errors become DeviceErrors at the next submission or read-back (the
  // command line). Off: they are only collected, for take_messages() (tests).
  bool errors_throw = true;
  SimulatedFault simulate = SimulatedFault::none;
  // Off: Dawn's Null backend and CPU fallback adapters other than lavapipe are refused
  // (adapter_choice.h) with DeviceError no_device. On: any adapter Dawn offers.
  bool allow_fallback_adapter = false;
};

class DawnContext {
 public:
  // Throws DeviceError (no_device) when Dawn offers no adapter or device, or only a
  // fallback adapter that options do not allow.
  static std::unique_ptr<DawnContext> create(const DawnOptions& options = {});
  ~DawnContext();
  DawnContext(const DawnContext&) = delete;
  DawnContext& operator=(const DawnContext&) = delete;

  const wgpu::Instance& instance() const { return instance_; }
  const wgpu::Adapter& adapter() const { return adapter_; }
  const wgpu::Device& device() const { return device_; }
  const wgpu::Queue& queue() const { return queue_; }
  const rhi::AdapterInfo& info() const { return info_; }
  bool has_timestamps() const { return timestamps_; }
  // Whether the adapter offers FeatureName::DualSourceBlending (a second blend source).
  bool offers_dual_source_blending() const { return dual_source_blending_; }
  SimulatedFault simulated_fault() const { return options_.simulate; }

  // Around the creation of a buffer or texture (`what` names it): an out-of-memory error
  // of Dawn's inside the scope, or a loss of the device for lack of memory (Dawn's Vulkan
  // backend loses the device when vkBindImageMemory returns VK_ERROR_OUT_OF_DEVICE_MEMORY),
  // throws DeviceError out_of_memory naming `what`.
  void begin_allocation() const;
  void end_allocation(std::string_view what);
  // Blocks until the future completes; `what` names the wait in the error.
  void wait(const wgpu::Future& future, std::string_view what) const;
  // Blocks until everything submitted so far has run.
  void wait_for_queue() const;
  // Throws DeviceError for a lost device, and (errors_throw) for the first uncaptured
  // error not reported yet.
  void check();
  // The uncaptured errors since the last call, one message each.
  std::vector<std::string> take_messages();

 private:
  explicit DawnContext(const DawnOptions& options) : options_(options) {}
  void request_adapter();
  void request_device();
  void on_error(wgpu::ErrorType type, std::string_view message);
  void on_lost(wgpu::DeviceLostReason reason, std::string_view message);

  DawnOptions options_;
  wgpu::Instance instance_;
  wgpu::Adapter adapter_;
  wgpu::Device device_;
  wgpu::Queue queue_;
  rhi::AdapterInfo info_;
  bool timestamps_ = false;
  bool dual_source_blending_ = false;
  std::mutex mutex_;  // guards what the callbacks write
  std::vector<std::string> messages_;
  size_t reported_ = 0;  // messages_ already thrown as DeviceErrors
  bool out_of_memory_ = false;
  std::string lost_;
  bool lost_for_memory_ = false;  // the loss's message names a Vulkan out-of-memory result
};

}  // namespace volgraph::webgpu
