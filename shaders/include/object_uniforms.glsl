// Per-object block, set 1 of every pass that rasterises the scene (passes/plumbing/scene_geometry.cpp).
#ifndef VOLGRAPH_OBJECT_UNIFORMS_GLSL
#define VOLGRAPH_OBJECT_UNIFORMS_GLSL

// graph/scene/scene.h's AlphaMode and VolumeKind, as the block codes them.
const int kAlphaOpaque = 0, kAlphaMask = 1, kAlphaBlend = 2;
const int kVolumeThinWalled = 0, kVolumeShell = 1, kVolumeSolid = 2;

#include "object_uniforms.h"
layout(set = 1, binding = 0) uniform ObjectUniformsBlock { ObjectUniforms object; };

#endif
