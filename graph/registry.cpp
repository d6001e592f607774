#include "graph/registry.h"

#include <stdexcept>

namespace volgraph {
namespace {

// A size's parameters are handles into its own table (SizeSpec): one from another
// table would read some other parameter, or none.
void check_size_params(const PassDecl& decl, const SlotDecl& slot) {
  auto fail = [&](const std::string& why) {
    throw std::logic_error("pass type " + decl.name + ": slot \"" + slot.name + "\"'s size " + why);
  };
  for (uint16_t p : slot.size.params()) {
    if (p >= decl.params.size()) fail("names parameter " + std::to_string(p) + " of " + std::to_string(decl.params.size()));
    const ParamDecl& param = decl.params[p];
    const bool choice_divisor = slot.size.divisor_param == p && !slot.size.divisor_choices.empty();
    if (param.type != (choice_divisor ? ParamType::choice : ParamType::integer)) {
      fail("reads parameter \"" + param.name + "\" (" + std::string(param_type_name(param.type)) + ") as " +
           (choice_divisor ? "a choice" : "an integer"));
    }
  }
}

}  // namespace

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
  for (const SlotDecl& slot : decl.slots) check_size_params(decl, slot);
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
