// VOLUME_FN: how the volume-visualization headers written once for GLSL and C++
// (volume_phantom.h, volume_transfer.h) declare their functions: `inline` in C++, nothing in GLSL.
#ifndef VOLGRAPH_VOLUME_FN_H
#define VOLGRAPH_VOLUME_FN_H
#ifdef __cplusplus
#define VOLUME_FN inline
#else
#define VOLUME_FN
#endif
#endif  // VOLGRAPH_VOLUME_FN_H
