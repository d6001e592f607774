// The scene's lights as passes receive them in a uniform block (std140). CPU side:
// passes/plumbing/light_list.h packs them.
#ifndef VOLGRAPH_LIGHT_LIST_GLSL
#define VOLGRAPH_LIGHT_LIST_GLSL
#include "lighting.glsl"

const int MAX_LIGHTS = 16;

struct LightList {
  ivec4 counts;  // x: lights
  Light lights[MAX_LIGHTS];
};

#endif
