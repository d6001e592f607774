// scene_probe's per-face block (passes/scene_probe.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_SCENE_PROBE_PARAMS_H
#define VOLGRAPH_SCENE_PROBE_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(SceneProbeFace) {
  vec4 face;  // x the face (0–5: +x, −x, +y, −y, +z, −z), y its side in texels
};
GPU_END

#endif  // VOLGRAPH_SCENE_PROBE_PARAMS_H
