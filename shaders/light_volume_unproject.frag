#version 450
#extension GL_GOOGLE_include_directive : require
// light_volume, first draw: the shadow map's clip space back to the world (the inverse of
// its view-projection, by cofactors: WGSL has no inverse()) into the light_frame image
// (shaders/include/light_volume.glsl gives its layout).
#include "include/light_volume.glsl"
#include "include/shadow_view.glsl"

layout(set = 0, binding = 0) uniform ShadowBlock { ShadowView view; } shadow;
layout(location = 0) out vec4 texel;

struct Inverse {
  mat4 matrix;
  float determinant;
};

// Laplace expansion along the first two rows against the last two (2×2 minors s and c).
Inverse inverse_of(mat4 m) {
  // a(r, c) = m[c][r]
  const float s0 = m[0][0] * m[1][1] - m[1][0] * m[0][1], s1 = m[0][0] * m[2][1] - m[2][0] * m[0][1];
  const float s2 = m[0][0] * m[3][1] - m[3][0] * m[0][1], s3 = m[1][0] * m[2][1] - m[2][0] * m[1][1];
  const float s4 = m[1][0] * m[3][1] - m[3][0] * m[1][1], s5 = m[2][0] * m[3][1] - m[3][0] * m[2][1];
  const float c5 = m[2][2] * m[3][3] - m[3][2] * m[2][3], c4 = m[1][2] * m[3][3] - m[3][2] * m[1][3];
  const float c3 = m[1][2] * m[2][3] - m[2][2] * m[1][3], c2 = m[0][2] * m[3][3] - m[3][2] * m[0][3];
  const float c1 = m[0][2] * m[2][3] - m[2][2] * m[0][3], c0 = m[0][2] * m[1][3] - m[1][2] * m[0][3];
  const float det = s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
  mat4 b;  // b[c][r]: the adjugate's entry (r, c)
  b[0][0] = m[1][1] * c5 - m[2][1] * c4 + m[3][1] * c3;
  b[1][0] = -m[1][0] * c5 + m[2][0] * c4 - m[3][0] * c3;
  b[2][0] = m[1][3] * s5 - m[2][3] * s4 + m[3][3] * s3;
  b[3][0] = -m[1][2] * s5 + m[2][2] * s4 - m[3][2] * s3;
  b[0][1] = -m[0][1] * c5 + m[2][1] * c2 - m[3][1] * c1;
  b[1][1] = m[0][0] * c5 - m[2][0] * c2 + m[3][0] * c1;
  b[2][1] = -m[0][3] * s5 + m[2][3] * s2 - m[3][3] * s1;
  b[3][1] = m[0][2] * s5 - m[2][2] * s2 + m[3][2] * s1;
  b[0][2] = m[0][1] * c4 - m[1][1] * c2 + m[3][1] * c0;
  b[1][2] = -m[0][0] * c4 + m[1][0] * c2 - m[3][0] * c0;
  b[2][2] = m[0][3] * s4 - m[1][3] * s2 + m[3][3] * s0;
  b[3][2] = -m[0][2] * s4 + m[1][2] * s2 - m[3][2] * s0;
  b[0][3] = -m[0][1] * c3 + m[1][1] * c1 - m[2][1] * c0;
  b[1][3] = m[0][0] * c3 - m[1][0] * c1 + m[2][0] * c0;
  b[2][3] = -m[0][3] * s3 + m[1][3] * s1 - m[2][3] * s0;
  b[3][3] = m[0][2] * s3 - m[1][2] * s1 + m[2][2] * s0;
  return Inverse(b * (1.0 / det), det);
}

void main() {
  const Inverse inv = inverse_of(shadow.view.light_view_projection);
  const int i = int(gl_FragCoord.x);
  texel = i < 4 ? inv.matrix[i] : vec4(inv.determinant < 0.0 ? -1.0 : 1.0, shadow.view.params.w, 0.0, 0.0);
}
