// The 1D transfer function on the CPU: shaders/include/volume_transfer.h compiled as C++ with
// GLM's types, and the tables volume_visualize's `transfer` parameter names (its presets).
#pragma once

#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

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

// A 2D table (volume_transfer_table_position's layout): W × H texels, row j at gradient
// j/(H − 1)·gradient_max, texel (i, j) at rgba[j·W + i]; the lookup the shader makes with
// texelFetch, bilinear by volume_transfer_table_mix.
struct TransferTable2d {
  int width = 1, height = 1;
  std::vector<vec4> rgba;
  float gradient_max = 1.0f;

  vec4 texel(int i, int j) const { return rgba[size_t(std::min(j, height - 1)) * size_t(width) + size_t(std::min(i, width - 1))]; }
  vec4 operator()(float density, float gradient_magnitude) const {
    const vec2 at = volume_transfer_table_position(density, gradient_magnitude, gradient_max, vec2(float(width), float(height)));
    const int i = int(floor(at.x)), j = int(floor(at.y));
    return volume_transfer_table_mix(texel(i, j), texel(i + 1, j), texel(i, j + 1), texel(i + 1, j + 1), at - vec2(float(i), float(j)));
  }
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
