// What shadow_map tells the passes that sample it (its light_view buffer, std140).
#ifndef VOLGRAPH_SHADOW_VIEW_GLSL
#define VOLGRAPH_SHADOW_VIEW_GLSL

#include "shadow_view.h"  // struct ShadowView

#endif
