#version 450
// Test only: a combined image sampler, which WebGPU does not have.
layout(set = 0, binding = 0) uniform sampler2D image;
layout(location = 0) out vec4 color;

void main() { color = texture(image, vec2(0.5)); }
