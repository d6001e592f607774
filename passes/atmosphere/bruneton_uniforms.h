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

}  // namespace volgraph
