// The clouds' temporal upsampling (Schneider & Vos 2015): cloud_march marches one pixel of
// each update_block × update_block block per frame, cloud_temporal rebuilds the rest. Both
// name the pixel the same way: frame % B² taken through the B × B Bayer order, so every
// pixel of a block is marched once in B² frames and consecutive ones lie far apart.
#pragma once

#include <array>
#include <cstdint>

namespace volgraph::clouds {

// The rank of pixel (x, y) in the n × n Bayer order (n a power of two): M(2n)(x, y) =
// 4·M(n)(x mod n, y mod n) + M(2)(x / n, y / n), M(2) = 0 2 / 3 1 — the coarsest quadrant
// is the least significant digit, so consecutive ranks lie far apart.
constexpr int bayer_rank(int x, int y, int n) {
  int rank = 0, scale = 1;
  for (int half = n / 2; half >= 1; half /= 2, scale *= 4) {
    const int qx = (x / half) % 2, qy = (y / half) % 2;
    rank += scale * (qx == qy ? (qx == 0 ? 0 : 1) : (qx == 1 ? 2 : 3));
  }
  return rank;
}

// The pixel inside each block that frame `frame` marches: the one of Bayer rank frame % B².
constexpr std::array<int32_t, 2> marched_offset(uint64_t frame, int block) {
  const int rank = int(frame % uint64_t(block * block));
  for (int y = 0; y < block; ++y) {
    for (int x = 0; x < block; ++x) {
      if (bayer_rank(x, y, block) == rank) return {x, y};
    }
  }
  return {0, 0};
}

// Update blocks the Bayer order is defined for (powers of two).
constexpr bool valid_update_block(int64_t block) { return block == 1 || block == 2 || block == 4; }

}  // namespace volgraph::clouds
