#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque scene, no shadow map: Lambertian reflection of every light (DESIGN.md units),
// ambient irradiance and emission; surfaces lit on the side seen.
float light_visibility(int light, vec3 p) { return 1.0; }
#include "include/scene_shading.glsl"
