// The material's textures, set 1 beside the object block of every pass that shades the
// scene (passes/plumbing/scene_geometry.cpp): sRGB images (the format decodes them to linear)
// that multiply the block's factors; 1×1 white where a material has none.
#ifndef VOLGRAPH_MATERIAL_TEXTURES_GLSL
#define VOLGRAPH_MATERIAL_TEXTURES_GLSL

layout(set = 1, binding = 1) uniform texture2D base_color_texture;
layout(set = 1, binding = 2) uniform texture2D emissive_texture;
layout(set = 1, binding = 3) uniform sampler material_sampler;

vec3 material_albedo(vec3 factor, vec2 uv) { return factor * texture(sampler2D(base_color_texture, material_sampler), uv).rgb; }
vec3 material_emission(vec3 factor, vec2 uv) { return factor * texture(sampler2D(emissive_texture, material_sampler), uv).rgb; }
// Coverage α: the factor times the base colour texture's alpha (stored linear).
float material_coverage(float factor, vec2 uv) { return factor * texture(sampler2D(base_color_texture, material_sampler), uv).a; }

#endif
