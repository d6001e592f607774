// How a benchmark names the device its times come from: lavapipe (Mesa's llvmpipe) runs
// the "GPU" on this machine's CPU, which every time printed beside it must say.
#pragma once

#include <string>

namespace volgraph::bench {

inline std::string device_label(const std::string& device_name) {
  if (device_name.find("llvmpipe") != std::string::npos) return device_name + ", lavapipe (CPU): its \"GPU\" is this CPU";
  return device_name;
}

}  // namespace volgraph::bench
