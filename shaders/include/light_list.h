// The scene's lights as passes receive them in a uniform block (std140; C++ packs them in
// passes/plumbing/light_list.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_LIGHT_LIST_H
#define VOLGRAPH_LIGHT_LIST_H
#include "gpu_struct.h"
#include "light.h"

// The most lights a scene may have (physics::kMaxLights: the scene reader checks it).
#define GPU_MAX_LIGHTS 16

GPU_BEGIN
GPU_STRUCT(LightList) {
  ivec4 counts;  // x: lights
  Light lights[GPU_MAX_LIGHTS];
};
GPU_END

#endif  // VOLGRAPH_LIGHT_LIST_H
