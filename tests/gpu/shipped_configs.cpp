// The shipped configs for the GPU tests (shipped_configs.h).
#include "tests/gpu/shipped_configs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include "tests/support/source_dir.h"

namespace volgraph::testing {
namespace {

namespace fs = std::filesystem;
const fs::path kConfigs = fs::path(::volgraph::testing::source_dir()) / "configs";

}  // namespace

std::vector<std::string> shipped_configs() {
  std::vector<std::string> names;
  for (const fs::path& folder : {kConfigs, kConfigs / "tests"}) {
    for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
      if (e.path().extension() == ".json") names.push_back(fs::relative(e.path(), kConfigs).string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string config_path(const std::string& config) { return (kConfigs / config).string(); }

std::string config_test_name(const std::string& config) {
  std::string name = fs::path(config).replace_extension().string();
  for (char& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return name;
}

}  // namespace volgraph::testing
