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

}  // namespace volgraph
