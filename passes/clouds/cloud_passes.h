// The cloud passes' declarations (Schneider & Vos 2015), registered in passes/passes.cpp.
#pragma once

#include "graph/pass_decl.h"

namespace volgraph {

PassDecl cloud_noise_pass();  // passes/clouds/cloud_noise.cpp

}  // namespace volgraph
