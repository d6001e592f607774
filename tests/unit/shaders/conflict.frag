#version 450
// Test only: set 1, binding 2 is a texture here and a uniform buffer in conflict.vert.
layout(set = 1, binding = 2) uniform texture2D scale;
layout(set = 1, binding = 3) uniform sampler nearest;
layout(location = 0) out vec4 color;

void main() { color = texelFetch(sampler2D(scale, nearest), ivec2(0), 0); }
