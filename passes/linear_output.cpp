#include "passes/linear_output.h"

namespace volgraph {

Overrides linear_output(const Config& config, Overrides overrides) {
  for (const PassNode& pass : config.passes) {
    if (pass.type != "composite") continue;
    overrides.variants.push_back(pass.name + "=none");
    overrides.sets.push_back(pass.name + ".exposure=0");
  }
  return overrides;
}

LoadedConfig load_linear(const std::string& path, const PassRegistry& registry, const Overrides& overrides) {
  return load_config(path, registry, linear_output(load_config(path, registry, overrides).config, overrides));
}

}  // namespace volgraph
