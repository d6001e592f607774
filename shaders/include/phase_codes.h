// The phase functions by code: a fog pass's phase variant (its VariantDecl::shader_code)
// as its shader reads it. One file that both GLSL (#include) and C++ read, so the codes
// cannot drift apart; keep it to #defines of integers.
#ifndef VOLGRAPH_PHASE_CODES_H
#define VOLGRAPH_PHASE_CODES_H

#define PHASE_ISOTROPIC 0
#define PHASE_RAYLEIGH 1
#define PHASE_HG 2
#define PHASE_SCHLICK 3
#define PHASE_DUAL_HG 4

#endif
