#include "passes/passes.h"

namespace volgraph {

void register_builtin_passes(PassRegistry& registry) {
  registry.add(shadow_map_pass());
  registry.add(scene_pass());
  registry.add(composite_pass());
  registry.add(clear_pass());
  registry.add(copy_pass());
}

}  // namespace volgraph
