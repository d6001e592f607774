// The scene pass's uniform blocks (passes/scene.cpp writes them, std140).
#ifndef VOLGRAPH_SCENE_UNIFORMS_GLSL
#define VOLGRAPH_SCENE_UNIFORMS_GLSL
#include "light_list.glsl"
#include "media_field.glsl"

#include "scene_frame.h"
layout(set = 0, binding = 0) uniform SceneFrameBlock { SceneFrame frame; };

#include "object_uniforms.glsl"

#endif
