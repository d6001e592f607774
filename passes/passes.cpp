#include "passes/passes.h"

#include <algorithm>

#include "passes/plumbing/gltf.h"
#include "passes/register_pass.h"

namespace volgraph {

std::vector<PassFactory>& builtin_pass_factories() {
  static std::vector<PassFactory> factories;  // filled by the pass files' registrars before main
  return factories;
}

void register_builtin_passes(PassRegistry& registry) {
  std::vector<PassDecl> decls;
  for (PassFactory make : builtin_pass_factories()) decls.push_back(make());
  // By name: the registrars run in link order, which must not change listings or messages.
  std::sort(decls.begin(), decls.end(), [](const PassDecl& a, const PassDecl& b) { return a.name < b.name; });
  for (PassDecl& decl : decls) registry.add(std::move(decl));
  // glTF objects with translucent materials need the translucency pass (graph/ reads no glTF).
  registry.set_scene_annotator(plumbing::mark_translucent_gltf_objects);
}

}  // namespace volgraph
