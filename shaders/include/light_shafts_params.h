// light_shafts_screen.comp's parameters (passes/fog/light_shafts_screen.cpp), one text for
// GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_LIGHT_SHAFTS_PARAMS_H
#define VOLGRAPH_LIGHT_SHAFTS_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(LightShaftsParams) {
  vec4 sun;       // xy the sun's texture coordinate on the frame, z the fade (0: no shafts)
  vec4 radiance;  // rgb the sun's irradiance × exposure × fade (W/(m²·sr) per unit of gathered sky)
  vec4 march;     // x samples, y density, z weight, w decay (Mitchell 2007's names)
};
GPU_END

#endif  // VOLGRAPH_LIGHT_SHAFTS_PARAMS_H
