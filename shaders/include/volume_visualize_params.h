// volume_visualize's parameters (passes/volume/volume_visualize.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_VOLUME_VISUALIZE_PARAMS_H
#define VOLGRAPH_VOLUME_VISUALIZE_PARAMS_H
#include "gpu_struct.h"
#include "view_rays.h"
#include "volume_transfer.h"

// The variants' codes (VariantDecl::shader_code).
#define VOLUME_VISUALIZE_RAYMARCH 0
#define VOLUME_VISUALIZE_ISOSURFACE 1
#define VOLUME_VISUALIZE_SLICES 2
#define VOLUME_VISUALIZE_HALF_ANGLE 3

GPU_BEGIN
GPU_STRUCT(VolumeVisualizeParams) {
  ViewRays view;          // the camera's rays; position.w its near plane, forward.w its far one (m)
  vec4 box_min;           // xyz the volume's world box, lowest corner (m)
  vec4 box_max;           // xyz its highest corner (m)
  ivec4 march;            // x steps (slices: the slice count), y bisection steps, z knots, w VOLUME_VISUALIZE_*
  vec4 surface;           // x the iso density, y the table's reference step Δ₀ (m); slices: z the slices' spacing,
                          // w the farthest slice's view depth (m)
  vec4 gradient;          // the 2D transfer's ramp in |∇ρ| (1/m): x from 0 at, y to 1 at (y ≤ 0: the 1D table alone);
                          // z the 2D table's top row's |∇ρ| (1/m)
  vec4 light_direction;   // xyz toward the light (unit); w 1: a scene light, 0: the headlight
  vec4 light_irradiance;  // rgb E (W/m²)
  vec4 half_axis;         // half_angle: xyz the slices' axis s (unit, Kniss et al. 2003's half vector), w the first slice's s·p (m)
  vec4 light_u;           // half_angle: xyz the light buffer's x axis (unit, ⟂ the light), w the half side it covers (m)
  vec4 light_v;           // half_angle: xyz its y axis (unit); w its side (texels)
  vec4 half_angle_mode;   // half_angle: x 1 front to back (blended under), 0 back to front (over); y 1 light occlusion on, 0 off
  vec4 knot_density[VOLUME_TRANSFER_MAX_KNOTS];  // x each knot's density
  vec4 knot_rgba[VOLUME_TRANSFER_MAX_KNOTS];     // each knot's colour and opacity
};
GPU_END

#endif  // VOLGRAPH_VOLUME_VISUALIZE_PARAMS_H
