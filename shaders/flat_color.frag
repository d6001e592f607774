#version 450
// One colour from a uniform block (set 0, binding 0).
layout(set = 0, binding = 0) uniform FlatColor { vec4 color; } params;
layout(location = 0) out vec4 out_color;

void main() { out_color = params.color; }
