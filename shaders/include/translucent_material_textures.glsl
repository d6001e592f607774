// A translucent material's data textures (glTF's KHR_materials_transmission transmissionTexture,
// KHR_materials_volume thicknessTexture), set 1 beside material_textures.glsl's, in the passes
// that draw translucent surfaces and casters: stored linear (rgba8 unorm), the red channel
// multiplying the transmission factor, the green the thickness factor; 1×1 white where a
// material has none (passes/plumbing/scene_geometry.cpp binds them).
#ifndef VOLGRAPH_TRANSLUCENT_MATERIAL_TEXTURES_GLSL
#define VOLGRAPH_TRANSLUCENT_MATERIAL_TEXTURES_GLSL
#include "material_textures.glsl"

layout(set = 1, binding = 4) uniform texture2D transmission_texture;
layout(set = 1, binding = 5) uniform texture2D thickness_texture;

float material_transmission(float factor, vec2 uv) { return factor * texture(sampler2D(transmission_texture, material_sampler), uv).r; }
float material_thickness(float factor, vec2 uv) { return factor * texture(sampler2D(thickness_texture, material_sampler), uv).g; }

#endif
