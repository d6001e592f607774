// shaders/include/cube_face.h (one text for GLSL and C++): the directions of a cube's
// texels against Vulkan's face selection and (s, t) mapping (spec §16.5.4, table 17: the
// major axis picks the face, s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2), which WebGPU shares.
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "physics/cube_face.h"

namespace volgraph {
namespace {

using physics::cube::cube_face_direction;
using physics::cube::cube_face_of;
using physics::cube::cube_texel_direction;

// Table 17's sc, tc and ma for a direction on each face.
glm::vec3 spec_sc_tc_ma(int face, glm::vec3 r) {
  switch (face) {
    case 0: return {-r.z, -r.y, r.x};
    case 1: return {r.z, -r.y, r.x};
    case 2: return {r.x, r.z, r.y};
    case 3: return {r.x, -r.z, r.y};
    case 4: return {r.x, -r.y, r.z};
    default: return {-r.x, -r.y, r.z};
  }
}

TEST(CubeFace, FaceCentresAreTheAxesInVulkansOrder) {
  const std::array<glm::vec3, 6> axes = {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  for (int face = 0; face < 6; ++face) {
    const glm::vec3 d = cube_face_direction(face, {0.5f, 0.5f});
    EXPECT_EQ(d, axes[size_t(face)]) << "face " << face;
  }
}

// Every texel's direction selects its own face and maps back to its own centre (s, t) by
// the spec's table, to float rounding.
TEST(CubeFace, TexelDirectionsMapBackThroughTheSpecsTable) {
  constexpr int n = 7;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const glm::vec3 d = cube_texel_direction(face, {i, j}, n);
        EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
        ASSERT_EQ(cube_face_of(d), face) << i << ", " << j;
        const glm::vec3 m = spec_sc_tc_ma(face, d);
        EXPECT_NEAR((m.x / std::abs(m.z) + 1) / 2, (i + 0.5f) / n, 1e-6f) << "face " << face << " texel " << i << ", " << j;
        EXPECT_NEAR((m.y / std::abs(m.z) + 1) / 2, (j + 0.5f) / n, 1e-6f) << "face " << face << " texel " << i << ", " << j;
      }
    }
  }
}

}  // namespace
}  // namespace volgraph
