// The translucency pass's own block (passes/translucency/translucency.cpp writes it each frame), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_TRANSLUCENCY_PARAMS_H
#define VOLGRAPH_TRANSLUCENCY_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(TranslucencyParams) {
  vec4 camera;       // xyz: the camera's position; w: its near plane (m)
  vec4 environment;  // rgb: the radiance the specular reflection sees; w: the far plane (m)
  vec4 options;      // x: 1 where a froxel volume is wired; y: 1 where an aerial-perspective volume is;
                     // z: 1 where solids refract what lies behind them (refracted_color);
                     // w: the angle a pixel spans at the frame's centre (rad), 2 tan(fov_y/2) / height
  vec4 refraction;   // x: 1 where solids refract as spheres (refraction_shape sphere), 0 as slabs;
                     // y: 1 where an environment cube is wired (reflections, refracted rays screen space misses)
};
GPU_END

#endif  // VOLGRAPH_TRANSLUCENCY_PARAMS_H
