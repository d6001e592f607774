// The checkout's root folder, for tests and benchmarks that read configs, goldens and
// assets. Only source_dir.cpp is compiled with the path, so every other translation unit
// is the same in every checkout of a commit and the compile cache serves them all.
#pragma once

#include <string>

namespace volgraph::testing {

const std::string& source_dir();

}  // namespace volgraph::testing
