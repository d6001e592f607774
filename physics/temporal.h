// Temporal accumulation's blend (CPU twin of shaders/include/temporal_blend.glsl): an
// exponential moving average whose first frames are averaged equally — this frame's
// weight max(alpha, 1/(n + 1)) for a history of n frames (Schied et al. 2017, §4.1) —
// with the frame count carried beside the value, capped where alpha takes over.
#pragma once

#include <algorithm>
#include <cmath>

namespace volgraph::physics {

template <typename T>
struct Accumulated {
  T value = 0;
  T frames = 0;  // frames the value averages (the GLSL's alpha channel)
};

// `valid` false: no history (first frame, or a point the last frame did not see).
template <typename T>
Accumulated<T> temporal_blend(T current, Accumulated<T> history, bool valid, T alpha) {
  if (!valid) return {current, T(1)};
  const T frames = std::max(history.frames, T(1));
  const T weight = std::max(alpha, T(1) / (frames + T(1)));
  return {history.value + (current - history.value) * weight, std::min(frames + T(1), std::ceil(T(1) / alpha))};
}

}  // namespace volgraph::physics
