// webgpu_cpp_chained_struct.h — the chain headers of volgraph's Dawn-style C++ API
// (webgpu_cpp.h): every extension struct starts with one, laid out like WGPUChainedStruct.
// Dawn ships a header of this name; Dawn's own can replace this one.
#ifndef WEBGPU_CPP_CHAINED_STRUCT_H_
#define WEBGPU_CPP_CHAINED_STRUCT_H_

#include <cstddef>
#include <cstdint>

namespace wgpu {

enum class SType : uint32_t;

// Extends an input descriptor ("in" chains).
struct ChainedStruct {
  ChainedStruct const* nextInChain = nullptr;
  SType sType = SType(0u);
};

// Extends an output struct the implementation fills ("out" chains).
struct ChainedStructOut {
  ChainedStructOut* nextInChain = nullptr;
  SType sType = SType(0u);
};

}  // namespace wgpu

#endif  // WEBGPU_CPP_CHAINED_STRUCT_H_
