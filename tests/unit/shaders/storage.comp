#version 450
// Test only (spirv_reflect_test.cpp): storage textures of several kinds and formats,
// read-only and writable storage buffers, bindings declared out of order, set 1 unused.
layout(local_size_x = 4, local_size_y = 2, local_size_z = 1) in;

layout(set = 0, binding = 3, r32ui) uniform uimage2D counters;
layout(set = 0, binding = 0, rgba16f) uniform writeonly image3D volume;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D depth;
layout(set = 0, binding = 2, std430) readonly buffer Samples { vec4 values[]; } samples;

layout(set = 2, binding = 4, rgba8) uniform writeonly image2D ldr;
layout(set = 2, binding = 1, std430) buffer Results { uint count; vec4 values[]; } results;
layout(set = 2, binding = 0, std430) buffer PartlyReadOnly { readonly uint first; uint second; } partly;
layout(set = 2, binding = 2) uniform texture3D history;
layout(set = 2, binding = 3) uniform sampler linear;

void main() {
  const ivec3 cell = ivec3(gl_GlobalInvocationID);
  const vec4 value = samples.values[cell.x] + texture(sampler3D(history, linear), vec3(cell));
  imageStore(volume, cell, value);
  imageStore(depth, cell.xy, vec4(value.x));
  imageStore(ldr, cell.xy, value);
  imageAtomicAdd(counters, cell.xy, 1u);
  results.values[atomicAdd(results.count, 1u)] = value;
  partly.second = partly.first;
}
