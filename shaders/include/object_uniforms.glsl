// Per-object block, set 1 of every pass that rasterises the scene (shading/scene_geometry.cpp).
#ifndef VOLGRAPH_OBJECT_UNIFORMS_GLSL
#define VOLGRAPH_OBJECT_UNIFORMS_GLSL

layout(set = 1, binding = 0) uniform Object {
  mat4 model;
  mat4 normal_matrix;  // inverse transpose of the model's 3×3, in a mat4
  vec4 albedo;
  vec4 emissive;       // radiance
} object;

#endif
