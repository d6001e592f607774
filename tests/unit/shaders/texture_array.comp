#version 450
// Test only: an array of textures, which one WebGPU binding cannot hold.
layout(local_size_x = 1) in;
layout(set = 0, binding = 1) uniform texture2D layers[2];
layout(set = 0, binding = 2) uniform sampler nearest;
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D result;

void main() {
  imageStore(result, ivec2(0), texelFetch(sampler2D(layers[0], nearest), ivec2(0), 0) +
                                   texelFetch(sampler2D(layers[1], nearest), ivec2(0), 0));
}
