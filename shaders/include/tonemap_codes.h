// The tone maps by code: composite's variant (VariantDecl::shader_code) as its shader
// reads it (tonemap.glsl's `op`), equal to physics::ToneMap (physics/tonemap.h). One file
// that both GLSL (#include) and C++ read, so the codes cannot drift apart; keep it to
// #defines of integers.
#ifndef VOLGRAPH_TONEMAP_CODES_H
#define VOLGRAPH_TONEMAP_CODES_H

#define TONE_MAP_NONE 0
#define TONE_MAP_ACES 1
#define TONE_MAP_REINHARD 2

#endif
