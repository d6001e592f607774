#version 450
#extension GL_GOOGLE_include_directive : require
// volume_phantom (passes/volume/volume_phantom.cpp): the phantom's density, one texel an
// invocation, at its texel centre (shaders/include/volume_phantom.h: the text the CPU twin
// compiles too); r the density, g b a zero.
#include "include/volume_phantom.h"
#include "include/volume_phantom_params.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform VolumePhantomParamsBlock { VolumePhantomParams params; };
layout(set = 0, binding = 1, rgba16f) uniform writeonly image3D density;

void main() {
  const ivec3 texel = ivec3(gl_GlobalInvocationID.xyz), size = imageSize(density);
  if (any(greaterThanEqual(texel, size))) return;
  const vec3 p = (vec3(texel) + 0.5) / vec3(size);
  imageStore(density, texel, vec4(volume_phantom_density(params.phantom.x, p, params.shape.x, params.shape.y), 0.0, 0.0, 0.0));
}
