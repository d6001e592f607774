#version 450
// Test only: set 1, binding 2 is a uniform block Scale here as in conflict.vert, laid out
// differently (a float first, the vec4 at 16).
layout(set = 1, binding = 2) uniform Scale { float bias; vec4 factor; } scale;
layout(location = 0) out vec4 color;

void main() { color = scale.factor + scale.bias; }
