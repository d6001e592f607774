// Pass types by name. Built explicitly (no static registration): see passes/passes.h.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/pass_decl.h"

namespace volgraph {

class PassRegistry {
 public:
  // Adds a pass type; a second type of the same name is a programming error (throws).
  const PassDecl& add(PassDecl decl);
  const PassDecl* find(std::string_view name) const;
  std::vector<std::string> names() const;  // in registration order
  const std::vector<std::unique_ptr<PassDecl>>& all() const { return decls_; }

 private:
  std::vector<std::unique_ptr<PassDecl>> decls_;
};

}  // namespace volgraph
