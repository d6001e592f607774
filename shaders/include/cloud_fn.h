// CLOUD_FN: how the cloud headers written once for GLSL and C++ (cloud_noise.h,
// cloud_density.h, cloud_lighting.h) declare their functions: `inline` in C++, nothing in GLSL.
#ifndef VOLGRAPH_CLOUD_FN_H
#define VOLGRAPH_CLOUD_FN_H
#ifdef __cplusplus
#define CLOUD_FN inline
#else
#define CLOUD_FN
#endif
#endif  // VOLGRAPH_CLOUD_FN_H
