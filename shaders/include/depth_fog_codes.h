// depth_fog's fog factors by code: its variant (VariantDecl::shader_code) as
// shaders/depth_fog.comp reads it (params.fog.w). One file that both GLSL (#include) and
// C++ read, so the codes cannot drift apart; keep it to #defines of integers.
#ifndef VOLGRAPH_DEPTH_FOG_CODES_H
#define VOLGRAPH_DEPTH_FOG_CODES_H

#define DEPTH_FOG_LINEAR 0
#define DEPTH_FOG_EXPONENTIAL 1
#define DEPTH_FOG_EXPONENTIAL_SQUARED 2

#endif
