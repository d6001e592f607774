// Every pass type volgraph ships, registered into a registry the caller owns.
#pragma once

#include "graph/registry.h"

namespace volgraph {

// Registers every pass type whose file registers itself (VOLGRAPH_REGISTER_PASS,
// passes/register_pass.h), in order of their names.
void register_builtin_passes(PassRegistry& registry);

}  // namespace volgraph
