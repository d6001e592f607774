// Errors a GPU backend reports: what went wrong on the device, as such.
#pragma once

#include <stdexcept>
#include <string>

namespace volgraph {

class DeviceError : public std::runtime_error {
 public:
  enum class Kind { no_device, unsupported, out_of_memory, device_lost, other };
  DeviceError(Kind kind, const std::string& message) : std::runtime_error(message), kind(kind) {}
  Kind kind;
};

// A failure a backend acts out on request (VOLGRAPH_SIMULATE_FAULT), so that reporting
// is tested on a driver that never fails: every allocation runs out of memory, or every
// submission loses the device.
enum class SimulatedFault { none, out_of_memory, device_lost };

}  // namespace volgraph
