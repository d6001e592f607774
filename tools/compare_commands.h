// The comparison commands: `volgraph ab` (two settings of one config in time and error,
// report.json and report.html), `volgraph sweep` (every point of a sweep spec, resumable,
// as jobs for GNU parallel or Slurm, merged) and `volgraph tune` (the fastest point under
// an error budget, as a config overlay).
#pragma once

#include "graph/registry.h"
#include "tools/command_line.h"

namespace volgraph {

int run_ab(const Args& args, const PassRegistry& registry);
int run_sweep_command(const Args& args, const PassRegistry& registry);
int run_tune(const Args& args, const PassRegistry& registry);

}  // namespace volgraph
