// A cube map's faces and directions (Vulkan spec §16.5.4 "Cube Map Face Selection",
// table 17; WebGPU samples cubes the same way): face 0–5 is +x, −x, +y, −y, +z, −z; on a
// face, s = 2u − 1 right and t = 2v − 1 down (v = 0 the face's first row), and the
// direction of (s, t) is, per face: +x (1, −t, −s), −x (−1, −t, s), +y (s, 1, t),
// −y (s, −1, −t), +z (s, −t, 1), −z (−s, −t, −1), unnormalised.
//
// ONE TEXT FOR BOTH SIDES, as cloud_lighting.h: GLSL includes this file, C++ includes it
// inside a namespace with GLM's types (physics/cube_face.h).
#ifndef VOLGRAPH_CUBE_FACE_H
#define VOLGRAPH_CUBE_FACE_H

#ifdef __cplusplus
#define CUBE_FN inline
#else
#define CUBE_FN
#endif

// The unit direction through point `uv` ([0, 1]², row-major from the face's top left) of `face`.
CUBE_FN vec3 cube_face_direction(int face, vec2 uv) {
  const float s = 2.0f * uv.x - 1.0f, t = 2.0f * uv.y - 1.0f;
  vec3 d = vec3(-s, -t, -1.0f);
  if (face == 0) d = vec3(1.0f, -t, -s);
  if (face == 1) d = vec3(-1.0f, -t, s);
  if (face == 2) d = vec3(s, 1.0f, t);
  if (face == 3) d = vec3(s, -1.0f, -t);
  if (face == 4) d = vec3(s, -t, 1.0f);
  return normalize(d);
}

// The direction through the centre of texel `texel` of a face `size` texels wide.
CUBE_FN vec3 cube_texel_direction(int face, ivec2 texel, int size) {
  return cube_face_direction(face, (vec2(texel) + vec2(0.5f)) / float(size));
}

// The face a direction selects: its largest component's axis and sign (ties: x before y before z).
CUBE_FN int cube_face_of(vec3 d) {
  const vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
  return d.z >= 0.0f ? 4 : 5;
}

#endif
