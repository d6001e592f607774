#version 450
// Test only: a fifth descriptor set (set 4); WebGPU has four.
layout(local_size_x = 1) in;
layout(set = 4, binding = 0, std430) buffer Result { uint value; } result;

void main() { result.value = 1u; }
