#version 450
#extension GL_GOOGLE_include_directive : require
// Weighted blended OIT's resolve, first draw: the colour behind × the revealage.
#include "include/oit_resolve.glsl"

layout(location = 0) out vec4 factor;
void main() { factor = vec4(revealage_at(ivec2(gl_FragCoord.xy)), 1.0); }
