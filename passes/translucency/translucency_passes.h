// The translucency family's pass types (RTR4 §14.5), one declaration per technique file.
#pragma once

#include "graph/pass_decl.h"

namespace volgraph {

PassDecl translucency_pass();  // passes/translucency/translucency.cpp

}  // namespace volgraph
