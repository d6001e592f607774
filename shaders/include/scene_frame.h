// The scene pass's frame (passes/scene.cpp writes it; the translucency pass binds the same
// buffer), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_SCENE_FRAME_H
#define VOLGRAPH_SCENE_FRAME_H
#include "gpu_struct.h"
#include "light_list.h"
#include "media_field.h"

GPU_BEGIN
GPU_STRUCT(SceneFrame) {
  mat4 view_projection;
  vec4 ambient_irradiance;  // rgb, W/m²
  LightList light_list;
  MediaField media;  // the global and height fog (no volumes): they dim the light toward each surface
};
GPU_END

#endif  // VOLGRAPH_SCENE_FRAME_H
