#version 450
// volume_visualize's slices (passes/volume/volume_visualize.cpp): one triangle covering the
// viewport per instance, instance k the k-th slice from the back (its depth in the fragment).
layout(location = 0) flat out int slice;

void main() {
  const vec2 corner = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
  slice = gl_InstanceIndex;
}
