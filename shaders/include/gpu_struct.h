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
struct alignas(8) vec2 { float x, y; };
struct alignas(8) ivec2 { int32_t x, y; };
struct alignas(8) uvec2 { uint32_t x, y; };
struct alignas(16) vec4 { float x, y, z, w; };
struct alignas(16) ivec4 { int32_t x, y, z, w; };
struct alignas(16) uvec4 { uint32_t x, y, z, w; };
struct alignas(16) mat4 { vec4 columns[4]; };  // column-major, as GLSL
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
