// VOXEL_FN: how the voxel headers written once for GLSL and C++ (voxel_overlap.h,
// voxel_shading.h) declare their functions: `inline` in C++, nothing in GLSL.
#ifndef VOLGRAPH_VOXEL_FN_H
#define VOLGRAPH_VOXEL_FN_H
#ifdef __cplusplus
#define VOXEL_FN inline
#else
#define VOXEL_FN
#endif
#endif  // VOLGRAPH_VOXEL_FN_H
