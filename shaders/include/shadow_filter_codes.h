// shadow_map's filters by code: its variant (VariantDecl::shader_code), which it writes
// to its light_view block (ShadowView.mode.x) for every pass that samples the map
// (shadow_lookup.glsl). One file that both GLSL (#include) and C++ read, so the codes
// cannot drift apart; keep it to #defines of integers.
#ifndef VOLGRAPH_SHADOW_FILTER_CODES_H
#define VOLGRAPH_SHADOW_FILTER_CODES_H

#define SHADOW_FILTER_HARD 0
#define SHADOW_FILTER_PCF 1

#endif
