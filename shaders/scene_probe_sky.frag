#version 450
#extension GL_GOOGLE_include_directive : require
// scene_probe: the sky cube behind a face's surfaces (passes/scene_probe.cpp). Drawn after
// them at the far plane (gl_FragDepth 1, tested less-or-equal, not written): only texels no
// surface covers take the sky toward their centre (include/cube_face.h), read from the
// wired cube (sky_cube.cube) — at a texel's centre of a cube of the same size, its texel.
#include "include/cube_face.h"
#include "include/scene_probe_params.h"

layout(set = 0, binding = 0) uniform Face { SceneProbeFace f; } probe;
layout(set = 0, binding = 1) uniform textureCube sky;
layout(set = 0, binding = 2) uniform sampler linear;

layout(location = 0) out vec4 color;

void main() {
  const vec3 direction = cube_texel_direction(int(probe.f.face.x), ivec2(gl_FragCoord.xy), int(probe.f.face.y));
  gl_FragDepth = 1.0;
  color = vec4(textureLod(samplerCube(sky, linear), direction, 0.0).rgb, 1.0);
}
