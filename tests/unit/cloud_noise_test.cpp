// The cloud noises (shaders/include/cloud_noise.h, compiled as C++ by physics/cloud_noise.h):
// ranges, tiling (each texture repeats across its edges with no seam), the lattice's exact
// zeros, the Perlin-Worley remap's bounds, and the seed.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/cloud_noise.h"

namespace volgraph::physics {
namespace {

using namespace cloud_noise;

// Every channel of the shape and detail textures' texels, sampled on a grid of n³ centres.
template <typename Texel>
std::vector<glm::vec4> grid(Texel texel, int n) {
  std::vector<glm::vec4> out;
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) out.push_back(texel(glm::vec3((x + 0.5f) / n, (y + 0.5f) / n, (z + 0.5f) / n)));
    }
  }
  return out;
}

TEST(CloudNoise, TexelsSpanTheUnitRangeInEveryChannel) {
  for (const auto& [name, texels] : {std::pair{"shape", grid([](glm::vec3 p) { return cloud_shape_texel(p, 0u); }, 24)},
                                     std::pair{"detail", grid([](glm::vec3 p) { return cloud_detail_texel(p, 0u); }, 24)}}) {
    for (int c = 0; c < 3; ++c) {
      double lo = 1, hi = 0, sum = 0;
      for (const glm::vec4& t : texels) {
        ASSERT_TRUE(std::isfinite(t[c]));
        lo = std::min(lo, double(t[c]));
        hi = std::max(hi, double(t[c]));
        sum += t[c];
      }
      EXPECT_GE(lo, 0.0) << name << " channel " << c;
      EXPECT_LE(hi, 1.0) << name << " channel " << c;
      EXPECT_GT(hi - lo, 0.4) << name << " channel " << c << ": a noise, not a constant";
      const double mean = sum / double(texels.size());
      EXPECT_GT(mean, 0.2) << name << " channel " << c;
      EXPECT_LT(mean, 0.8) << name << " channel " << c;
    }
  }
}

TEST(CloudNoise, EveryNoiseRepeatsAcrossItsTile) {
  // uvw and uvw + 1 along each axis: the same lattice points, wrapped (float rounding only).
  for (float u : {0.03f, 0.37f, 0.81f}) {
    for (int axis = 0; axis < 3; ++axis) {
      glm::vec3 p(u, 0.5f * u + 0.2f, 0.9f - u), q = p;
      q[axis] += 1.0f;
      for (int c = 0; c < 4; ++c) {
        EXPECT_NEAR(cloud_shape_texel(p, 3u)[c], cloud_shape_texel(q, 3u)[c], 2e-5f) << "axis " << axis << " channel " << c;
        EXPECT_NEAR(cloud_detail_texel(p, 3u)[c], cloud_detail_texel(q, 3u)[c], 2e-5f) << "axis " << axis << " channel " << c;
      }
      if (axis < 2) {
        glm::vec2 a(p.x, p.y), b = a;
        b[axis] += 1.0f;
        for (int c = 0; c < 2; ++c) EXPECT_NEAR(cloud_curl_texel(a, 1.0f / 128, 3u)[c], cloud_curl_texel(b, 1.0f / 128, 3u)[c], 2e-4f);
      }
    }
  }
}

TEST(CloudNoise, NoSeamWhereTheTileWraps) {
  // Neighbouring texels across the wrap (last, first) differ no more than neighbours inside.
  constexpr int n = 32;
  const auto at = [&](int x, int y) { return cloud_shape_texel(glm::vec3((x + 0.5f) / n, (y + 0.5f) / n, 0.25f), 0u); };
  for (int c = 0; c < 4; ++c) {
    float inside = 0, across = 0;
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x + 1 < n; ++x) inside = std::max(inside, std::abs(at(x + 1, y)[c] - at(x, y)[c]));
      across = std::max(across, std::abs(at(0, y)[c] - at(n - 1, y)[c]));
    }
    EXPECT_LE(across, inside) << "channel " << c;
  }
}

TEST(CloudNoise, GradientNoiseVanishesOnItsLattice) {
  for (int x = 0; x < 4; ++x) {
    for (int z = 0; z < 4; ++z) EXPECT_EQ(cloud_perlin(glm::vec3(float(x), 2.0f, float(z)), 4, 9u), 0.0f);
  }
}

TEST(CloudNoise, PerlinWorleyStaysBetweenItsInputs) {
  EXPECT_FLOAT_EQ(cloud_perlin_worley(0.3f, 1.0f), 0.3f);   // bright Worley: Perlin as it is
  EXPECT_FLOAT_EQ(cloud_perlin_worley(0.0f, 0.0f), 0.5f);   // dark Worley: Perlin dilated to (p + 1) / 2
  EXPECT_FLOAT_EQ(cloud_perlin_worley(1.0f, 0.25f), 1.0f);
  for (float p = 0; p <= 1; p += 0.125f) {
    for (float w = 0; w <= 1; w += 0.125f) {
      const float v = cloud_perlin_worley(p, w);
      EXPECT_GE(v, p - 1e-6f);
      EXPECT_LE(v, 1.0f);
    }
  }
}

TEST(CloudNoise, TheSeedChangesTheNoise) {
  const glm::vec3 p(0.3f, 0.6f, 0.1f);
  EXPECT_NE(cloud_shape_texel(p, 0u)[0], cloud_shape_texel(p, 1u)[0]);
  EXPECT_NE(cloud_detail_texel(p, 0u)[0], cloud_detail_texel(p, 1u)[0]);
}

}  // namespace
}  // namespace volgraph::physics
