// scatter_integrate's steps by code: its variant (VariantDecl::shader_code) as its
// shader reads it (Params.method.x). One file that both GLSL (#include) and C++ read, so
// the codes cannot drift apart; keep it to #defines of integers.
#ifndef VOLGRAPH_INTEGRATION_CODES_H
#define VOLGRAPH_INTEGRATION_CODES_H

#define INTEGRATE_WRONSKI 0
#define INTEGRATE_HILLAIRE 1

#endif
