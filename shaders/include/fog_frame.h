// What froxel_voxelize tells the other fog passes of the frame (its frame buffer, std140, packed by passes/fog/fog_frame.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_FOG_FRAME_H
#define VOLGRAPH_FOG_FRAME_H
#include "gpu_struct.h"
#include "view_rays.h"
#include "froxel_grid.h"
#include "light_list.h"
#include "media_field.h"

GPU_BEGIN
GPU_STRUCT(FogFrame) {
  ViewRays view;       // position.w: the camera's near plane, forward.w: its far plane (m)
  FroxelGrid grid;
  vec4 jitter;         // xyz: this frame's sample offset inside each froxel (froxel units, within ±0.5); w: frame
  vec4 ambient;        // rgb: ambient radiance (W/(m²·sr)) scattered by the media
  LightList light_list;
  MediaField media;
};
GPU_END

#endif  // VOLGRAPH_FOG_FRAME_H
