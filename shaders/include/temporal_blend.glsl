// Temporal accumulation's blend, shared by froxel_temporal and pixel_temporal: an
// exponential moving average of each frame's value (Hillaire 2015, p. 9; Karis 2014)
// whose first frames are averaged equally — the weight of this frame is
// max(alpha, 1/(n + 1)) for a history of n frames (Schied et al. 2017, §4.1), so a still
// view converges at once and then keeps a bounded memory. The history's frame count
// travels in the alpha channel, capped where alpha takes over. CPU twin:
// physics/temporal.h.
#ifndef VOLGRAPH_TEMPORAL_BLEND_GLSL
#define VOLGRAPH_TEMPORAL_BLEND_GLSL

// `history`: rgb last frame's blend, a its frame count; valid false: no history here
// (the first frame, or a point last frame did not see). Returns rgb the blend, a the
// new count.
vec4 temporal_blend(vec4 current, vec4 history, bool valid, float alpha) {
  if (!valid) return vec4(current.rgb, 1.0);
  const float frames = max(history.a, 1.0);
  const float weight = max(alpha, 1.0 / (frames + 1.0));
  return vec4(mix(history.rgb, current.rgb, weight), min(frames + 1.0, ceil(1.0 / alpha)));
}

#endif
