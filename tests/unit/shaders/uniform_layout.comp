#version 450
// Test only (spirv_reflect_test.cpp): a uniform block whose std140 layout has the gaps and
// the packing a host struct easily gets wrong (offsets in the comments).
layout(local_size_x = 1) in;
layout(set = 0, binding = 0) uniform Layout {
  float a;     // 0
  vec3 b;      // 16: a vec3 aligns to 16
  float c;     // 28: packs after the vec3
  vec2 d;      // 32
  float e[2];  // 48: array stride 16, 32 bytes
  mat3 m;      // 80: three columns of stride 16, 48 bytes
  int last;    // 128; the block is 132 bytes
} u;
layout(set = 0, binding = 1, std430) buffer Result { float value; } result;

void main() { result.value = u.a + u.b.x + u.c + u.d.y + u.e[1] + u.m[2].z + float(u.last); }
