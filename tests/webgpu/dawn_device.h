// dawn_device.h — test helper: a Dawn instance, adapter and device through the C API of
// <webgpu/webgpu.h>, with the uncaptured errors and device loss recorded for the test.
#pragma once

#include <webgpu/webgpu.h>

#include <string>
#include <string_view>
#include <vector>

namespace volgraph::webgpu_test {

std::string to_string(WGPUStringView s);

// What the device's callbacks reported.
struct DeviceEvents {
  std::vector<std::string> uncaptured_errors;
  std::vector<std::string> lost;  // reason and message, one entry per loss
};

// Owns instance, adapter and device; each is null when it could not be created, and
// `failure` says why.
class DawnDevice {
 public:
  DawnDevice();
  ~DawnDevice();
  DawnDevice(const DawnDevice&) = delete;
  DawnDevice& operator=(const DawnDevice&) = delete;

  WGPUInstance instance = nullptr;
  WGPUAdapter adapter = nullptr;
  WGPUDevice device = nullptr;
  std::string failure;
  DeviceEvents events;

  // Waits (blocking) for a future of this instance.
  bool wait(WGPUFuture future) const;

 private:
  void request_adapter();
  void request_device();
};

}  // namespace volgraph::webgpu_test
