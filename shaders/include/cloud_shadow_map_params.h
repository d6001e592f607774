// cloud_shadow_map.comp's parameters (passes/clouds/cloud_shadow_map.cpp), one text for GLSL and C++ (gpu_struct.h).
// layer, cloud, scales and wind as cloud_march's (cloud_layer.glsl reads them by these names).
#ifndef VOLGRAPH_CLOUD_SHADOW_MAP_PARAMS_H
#define VOLGRAPH_CLOUD_SHADOW_MAP_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(CloudShadowMapParams) {
  vec4 plane;   // CloudShadowView's: x, z the centre, y the bottom plane's world y, w the side (m)
  vec4 to_sun;  // CloudShadowView's: xyz toward the sun (unit), w its light index (−1: none)
  vec4 layer;   // x bottom altitude, y top altitude, z planet radius, w the altitude of world y = 0 (m)
  vec4 cloud;   // x coverage, y type, z extinction (1/m at density 1)
  vec4 scales;  // x shape tile, y detail tile (m), z curl distortion (detail tiles)
  vec4 wind;    // xyz the noise's offset (m): wind × time
  vec4 weather; // the weather map's lookup (cloud_layer.glsl): x 1 / its size (1/m), yz its offset (m)
  ivec4 steps;  // x samples along the sun's ray through the layer, y layers (0: no transmittance map)
};
GPU_END

#endif  // VOLGRAPH_CLOUD_SHADOW_MAP_PARAMS_H
