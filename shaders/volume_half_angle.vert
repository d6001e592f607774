#version 450
// volume_visualize's half-angle slices (passes/volume/volume_visualize.cpp): one triangle
// covering the viewport, vertices 3k … 3k + 2 (draw(3, 1, 3k)) slice k from the light.
layout(location = 0) flat out int slice;

void main() {
  const int corner_index = gl_VertexIndex % 3;
  const vec2 corner = vec2(float((corner_index << 1) & 2), float(corner_index & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
  slice = gl_VertexIndex / 3;
}
