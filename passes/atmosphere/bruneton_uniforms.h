// Host mirrors of the Bruneton passes' uniform blocks (checked against the shaders'
// reflection when each pass sets up: plumbing::check_uniform_mirror).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace volgraph {

// atmosphere_bruneton_*.comp's Params.
struct GpuBrunetonTableParams {
  int32_t size[4];   // the scattering table's nu, mu_s, mu, r texels
  int32_t order[4];  // x: the scattering order of the step; y: 1 when it is within the pass's orders; z: trapezoids along each ray
  static constexpr std::array<uint64_t, 2> offsets() { return {offsetof(GpuBrunetonTableParams, size), offsetof(GpuBrunetonTableParams, order)}; }
};

// The shape of a scattering table of `width` × `height` × `depth` texels holding `nu`
// slices of mu_s texels in x, mu in y and r in z, as the tables' readers take it.
inline GpuBrunetonTableParams bruneton_table_shape(uint32_t width, uint32_t height, uint32_t depth, int64_t nu) {
  GpuBrunetonTableParams shape{};
  shape.size[0] = int32_t(nu);
  shape.size[1] = width / nu > 0 ? int32_t(width / nu) : 1;
  shape.size[2] = int32_t(height);
  shape.size[3] = int32_t(depth);
  return shape;
}

}  // namespace volgraph
