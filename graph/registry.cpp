#include "graph/registry.h"

#include <stdexcept>

namespace volgraph {

const PassDecl& PassRegistry::add(PassDecl decl) {
  if (find(decl.name)) throw std::logic_error("pass type registered twice: " + decl.name);
  if (decl.variants.empty()) throw std::logic_error("pass type without variants: " + decl.name);
  for (size_t i = 0; i < decl.slots.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (decl.slots[i].name == decl.slots[j].name) {
        throw std::logic_error("pass type " + decl.name + " declares slot \"" + decl.slots[i].name + "\" twice (a config could not name one of them)");
      }
    }
  }
  decls_.push_back(std::make_unique<PassDecl>(std::move(decl)));
  return *decls_.back();
}

const PassDecl* PassRegistry::find(std::string_view name) const {
  for (const auto& d : decls_) {
    if (d->name == name) return d.get();
  }
  return nullptr;
}

std::vector<std::string> PassRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& d : decls_) out.push_back(d->name);
  return out;
}

}  // namespace volgraph
