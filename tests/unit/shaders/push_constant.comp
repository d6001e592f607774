#version 450
// Test only: push constants, which WebGPU does not have.
layout(local_size_x = 1) in;
layout(push_constant) uniform Constants { uint value; } constants;
layout(set = 0, binding = 0, std430) buffer Result { uint value; } result;

void main() { result.value = constants.value; }
