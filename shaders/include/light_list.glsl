// The scene's lights as passes receive them in a uniform block (std140). CPU side:
// passes/plumbing/light_list.h packs them.
#ifndef VOLGRAPH_LIGHT_LIST_GLSL
#define VOLGRAPH_LIGHT_LIST_GLSL
#include "lighting.glsl"

#include "light_list.h"  // struct LightList, GPU_MAX_LIGHTS

const int MAX_LIGHTS = GPU_MAX_LIGHTS;

#endif
