#version 450
// A uniform block declared with its members inline (as composite.comp's was before its
// parameters became a struct written once): the host-struct checks' fixture.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D frame;
layout(set = 0, binding = 3) uniform CompositeParams {
  uvec2 size;
  float exposure_ev;
  int tone_map_op;
} params;

void main() {
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, params.size))) return;
  imageStore(frame, ivec2(pixel), vec4(params.exposure_ev, float(params.tone_map_op), 0.0, 1.0));
}
