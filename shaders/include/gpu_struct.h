// Structs written once for GLSL and C++ (Falcor's HostDeviceShared.slangh; Bruneton 2017
// compiles its GLSL as C++): a header under shaders/include/ declares each with
// GPU_STRUCT(Name) { … }; between GPU_BEGIN and GPU_END; a shader holds it in a block
// (`layout(set = 0, binding = 3) uniform VignetteBlock { VignetteParams params; };`, read as
// `params.lens` and bound as shaders::<shader>::params), and C++ fills volgraph::gpu::Name.
//
// The C++ types below have std140's alignments (vec2 8, vec4 and a struct 16), so a struct
// of them is laid out as std140 lays it out; there is no vec3 or mat3 (std140 pads them as
// C++ cannot) and a scalar array is refused by the checks (std140 strides it by 16). The
// build asserts every shared struct's size and member offsets against each shader that
// holds it, at compile time (shaders/binding_names.cpp writes the static_asserts into
// "shaders/bindings/<shader>.h").
#ifndef VOLGRAPH_GPU_STRUCT_H
#define VOLGRAPH_GPU_STRUCT_H

#ifdef __cplusplus
#include <cstdint>

namespace volgraph::gpu {
using uint = uint32_t;

// A GLSL vector: x, y, z, w, and [i] as GLSL indexes it.
template <typename T, int N, int Align>
struct alignas(Align) Vector;
template <typename T>
struct alignas(8) Vector<T, 2, 8> {
  T x, y;
  constexpr T& operator[](int i) { return i == 0 ? x : y; }
  constexpr const T& operator[](int i) const { return i == 0 ? x : y; }
};
template <typename T>
struct alignas(16) Vector<T, 4, 16> {
  T x, y, z, w;
  constexpr T& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
  constexpr const T& operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
};
using vec2 = Vector<float, 2, 8>;
using ivec2 = Vector<int32_t, 2, 8>;
using uvec2 = Vector<uint32_t, 2, 8>;
using vec4 = Vector<float, 4, 16>;
using ivec4 = Vector<int32_t, 4, 16>;
using uvec4 = Vector<uint32_t, 4, 16>;
struct alignas(16) mat4 { vec4 columns[4]; };  // column-major, as GLSL

// A vec4 of four floats the host computed (float[4] arrays of physics/).
constexpr vec4 vec4_of(const float (&v)[4]) { return {v[0], v[1], v[2], v[3]}; }
}  // namespace volgraph::gpu

#define GPU_BEGIN namespace volgraph::gpu {
#define GPU_END }
#define GPU_STRUCT(name) struct alignas(16) name
#else
#define GPU_BEGIN
#define GPU_END
#define GPU_STRUCT(name) struct name
#endif

#endif  // VOLGRAPH_GPU_STRUCT_H
