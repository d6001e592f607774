// GPU tests fail on any validation message; this prints them one per line.
#pragma once

#include <string>
#include <vector>

namespace volgraph::vulkan {

inline std::string joined(const std::vector<std::string>& messages) {
  std::string out;
  for (const auto& m : messages) out += m + "\n";
  return out;
}

}  // namespace volgraph::vulkan
