// The overrides that make a config's output the linear radiance the CPU reference
// computes: every composite pass at variant `none` and exposure 0 (no tone map, no
// exposure). What the accuracy tests, `volgraph ab` and `volgraph sweep` compare.
#pragma once

#include "graph/config/config.h"

namespace volgraph {

// `overrides` plus, for every composite pass of `config`, --variant NAME=none and
// --set NAME.exposure=0.
Overrides linear_output(const Config& config, Overrides overrides);

// Loads the config at `path` with linear_output applied (the config is read twice:
// first to find its composite passes).
LoadedConfig load_linear(const std::string& path, const PassRegistry& registry, const Overrides& overrides = {});

}  // namespace volgraph
