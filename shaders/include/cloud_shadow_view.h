// cloud_shadow_map's placement (passes/clouds/cloud_shadow_view.h computes it; the pass
// writes it to its `view` buffer, the readers hold it as their block's one member), one
// text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_CLOUD_SHADOW_VIEW_H
#define VOLGRAPH_CLOUD_SHADOW_VIEW_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(CloudShadowView) {
  vec4 plane;   // x, z the map's centre (world m), y the world height of the layer's bottom plane, w the square's side (m)
  vec4 to_sun;  // xyz unit toward the sun; w the sun's light index in the scene (−1: no sun, nothing shadowed)
};
GPU_END

#endif  // VOLGRAPH_CLOUD_SHADOW_VIEW_H
