// The shipped configs (configs/*.json, configs/tests/*.json) the GPU tests render, and
// the small frame they render them at (the suite runs on two CPU cores).
#pragma once

#include <string>
#include <vector>

#include "graph/resource.h"

namespace volgraph::testing {

inline constexpr Extent kConfigTestSize{64, 36, 1};

// Paths relative to configs/, sorted.
std::vector<std::string> shipped_configs();
std::string config_path(const std::string& config);
// "tests/lambert_plane.json" → "tests_lambert_plane" (test and golden image names).
std::string config_test_name(const std::string& config);

}  // namespace volgraph::testing
