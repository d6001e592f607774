#version 450
// Test only: set 1, binding 2 is a uniform buffer here and a texture in conflict.frag.
layout(set = 1, binding = 2) uniform Scale { vec4 factor; } scale;
layout(location = 0) in vec3 position;

void main() { gl_Position = vec4(position, 1.0) * scale.factor; }
