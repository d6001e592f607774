// The 1D transfer function on the CPU: shaders/include/volume_transfer.h compiled as C++ with
// GLM's types, and the tables volume_visualize's `transfer` parameter names (its presets).
#pragma once

#include <array>
#include <string_view>

#include <glm/glm.hpp>

namespace volgraph::physics::volume_transfer {

using namespace glm;

#include "shaders/include/volume_transfer.h"

// A table as the lookup reads it: knot i at density density[i].x with colour and opacity rgba[i].
struct TransferTable {
  std::array<vec4, VOLUME_TRANSFER_MAX_KNOTS> density{};
  std::array<vec4, VOLUME_TRANSFER_MAX_KNOTS> rgba{};
  int count = 0;

  void add(float at, vec4 value) {
    density[size_t(count)] = vec4(at, 0.0f, 0.0f, 0.0f);
    rgba[size_t(count)] = value;
    ++count;
  }
  vec4 operator()(float at) const { return volume_transfer_lookup(density.data(), rgba.data(), count, at); }
};

// The presets (volume_visualize's `transfer`):
//   shells:   transparent but for hats at the shells phantom's densities 0.25 (blue, faint),
//             0.5 (amber) and up to 1 (red, dense);
//   grey:     a ramp from transparent black at 0 to white of opacity 0.25 at 1;
//   constant: `colour` and `opacity` at every density (one knot).
inline TransferTable shells_transfer() {
  TransferTable t;
  t.add(0.0f, vec4(0.0f));
  t.add(0.2f, vec4(0.0f));
  t.add(0.25f, vec4(0.25f, 0.5f, 1.0f, 0.04f));
  t.add(0.3f, vec4(0.0f));
  t.add(0.45f, vec4(0.0f));
  t.add(0.5f, vec4(1.0f, 0.65f, 0.2f, 0.15f));
  t.add(0.55f, vec4(0.0f));
  t.add(1.0f, vec4(1.0f, 0.15f, 0.1f, 0.6f));
  return t;
}
inline TransferTable grey_transfer() {
  TransferTable t;
  t.add(0.0f, vec4(0.0f));
  t.add(1.0f, vec4(1.0f, 1.0f, 1.0f, 0.25f));
  return t;
}
inline TransferTable constant_transfer(vec3 colour, float opacity) {
  TransferTable t;
  t.add(0.0f, vec4(colour, opacity));
  return t;
}

}  // namespace volgraph::physics::volume_transfer
