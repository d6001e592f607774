// A pass type registers itself in its own file: at namespace scope,
//
//   VOLGRAPH_REGISTER_PASS(RaymarchFogTable, RaymarchFogExecution);
//
// adds pass_type<Table, Execution> (graph/execute/pass_execution.h) to the built-in pass
// types, which register_builtin_passes() (passes/passes.h) registers in order of their
// names, whatever order the linker runs the files' registrars in. The library is linked
// whole (passes/CMakeLists.txt), so no file's registrar is dropped.
#pragma once

#include <vector>

#include "graph/execute/pass_execution.h"

namespace volgraph {

using PassFactory = PassDecl (*)();

// The built-in pass types' factories, in the order their files' registrars ran.
std::vector<PassFactory>& builtin_pass_factories();

// Adds a factory when constructed: one object per pass type, made by the macro below.
struct BuiltinPassRegistrar {
  explicit BuiltinPassRegistrar(PassFactory factory) { builtin_pass_factories().push_back(factory); }
};

}  // namespace volgraph

#define VOLGRAPH_REGISTER_PASS(Table, Execution) \
  const ::volgraph::BuiltinPassRegistrar volgraph_registrar_##Table{&::volgraph::pass_type<Table, Execution>}
