// Every pass type volgraph ships, registered into a registry the caller owns.
#pragma once

#include "graph/registry.h"

namespace volgraph {

void register_builtin_passes(PassRegistry& registry);

// One declaration per technique file (passes/<name>.cpp).
PassDecl shadow_map_pass();
PassDecl scene_pass();
PassDecl composite_pass();
PassDecl clear_pass();
PassDecl copy_pass();
PassDecl vignette_pass();  // passes/post/vignette.cpp

}  // namespace volgraph
