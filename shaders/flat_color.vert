#version 450
// Positions straight to clip space; with flat_color.frag, a debug and test pipeline.
layout(location = 0) in vec3 position;

void main() { gl_Position = vec4(position, 1.0); }
