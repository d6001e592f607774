// A resource variable a shader declares, by name: its descriptor set and binding. The
// constants are generated from each shader's SPIR-V at build time
// (shaders/CMakeLists.txt, "shaders/bindings/<shader>.h"), so that C++ names a binding
// the GLSL declares instead of restating its numbers (rhi/bind_by_name.h binds by them).
#pragma once

#include <cstdint>

namespace volgraph::rhi {

struct ShaderBinding {
  uint32_t set = 0;
  uint32_t binding = 0;
  const char* name = "";  // the GLSL variable: a block's instance name, else its block name
};

}  // namespace volgraph::rhi
