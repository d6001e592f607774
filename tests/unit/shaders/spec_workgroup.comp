#version 450
// Test only: a workgroup size given by a specialisation constant, which reflection cannot read.
layout(local_size_x_id = 0, local_size_y = 2) in;
layout(set = 0, binding = 0, std430) buffer Result { uint value; } result;

void main() { result.value = 1u; }
