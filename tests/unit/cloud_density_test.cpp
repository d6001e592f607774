// The cloud layer's density (shaders/include/cloud_density.h, compiled as C++ by
// physics/cloud_density.h): the height fraction, the cloud types' height gradients, the
// coverage, the erosion's bounds, the extinction, and no NaN or infinity anywhere.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/cloud_density.h"

namespace volgraph::physics {
namespace {

using namespace cloud_density;

// n + 1 evenly spaced values from 0 to 1, both ends included.
std::vector<float> unit_steps(int n) {
  std::vector<float> out;
  for (int k = 0; k <= n; ++k) out.push_back(float(k) / float(n));
  return out;
}

// The profile's centroid ∫ h g(h) dh / ∫ g(h) dh by the midpoint rule, and its mass ∫ g.
struct ProfileMoments {
  double mass = 0, centroid = 0;
};
ProfileMoments profile_moments(float type) {
  constexpr int n = 4096;
  double mass = 0, moment = 0;
  for (int k = 0; k < n; ++k) {
    const double h = (k + 0.5) / n;
    const double g = cloud_height_gradient(float(h), type);
    mass += g / n;
    moment += h * g / n;
  }
  return {mass, moment / mass};
}

TEST(CloudDensity, HeightFractionIsZeroAtTheBottomOneAtTheTopAndClamped) {
  EXPECT_EQ(cloud_height_fraction(1500.0f, 1500.0f, 4000.0f), 0.0f);
  EXPECT_EQ(cloud_height_fraction(4000.0f, 1500.0f, 4000.0f), 1.0f);
  EXPECT_FLOAT_EQ(cloud_height_fraction(2750.0f, 1500.0f, 4000.0f), 0.5f);
  EXPECT_EQ(cloud_height_fraction(0.0f, 1500.0f, 4000.0f), 0.0f);      // below the layer
  EXPECT_EQ(cloud_height_fraction(9000.0f, 1500.0f, 4000.0f), 1.0f);   // above it
  EXPECT_EQ(cloud_height_fraction(-1e9f, 1500.0f, 4000.0f), 0.0f);
}

TEST(CloudDensity, RemapCarriesOneRangeToAnother) {
  EXPECT_FLOAT_EQ(cloud_remap(0.5f, 0.0f, 1.0f, 2.0f, 4.0f), 3.0f);
  EXPECT_FLOAT_EQ(cloud_remap(-0.5f, -0.5f, 1.0f, 0.0f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(cloud_remap(1.0f, -0.5f, 1.0f, 0.0f, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(cloud_remap(0.25f, -0.5f, 1.0f, 0.0f, 1.0f), 0.5f);
}

TEST(CloudDensity, EveryHeightGradientVanishesAtBothEndsAndRisesInside) {
  for (float type : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
    EXPECT_EQ(cloud_height_gradient(0.0f, type), 0.0f) << "type " << type;
    EXPECT_EQ(cloud_height_gradient(1.0f, type), 0.0f) << "type " << type;
    float peak = 0;
    for (float h : unit_steps(1000)) {
      const float g = cloud_height_gradient(h, type);
      EXPECT_GE(g, 0.0f) << "type " << type << " h " << h;
      EXPECT_LE(g, 1.0f) << "type " << type << " h " << h;
      peak = std::max(peak, g);
    }
    EXPECT_GT(peak, 0.9f) << "type " << type << ": the profile reaches full density inside";
    EXPECT_GT(profile_moments(type).mass, 0.02) << "type " << type;
  }
  // Inside each profile's plateau (between its rise and its fall) the gradient is positive.
  EXPECT_GT(cloud_height_gradient(0.07f, 0.0f), 0.5f);   // stratus: low
  EXPECT_GT(cloud_height_gradient(0.3f, 0.5f), 0.5f);    // cumulus
  EXPECT_GT(cloud_height_gradient(0.7f, 1.0f), 0.5f);    // cumulonimbus: tall
  EXPECT_EQ(cloud_height_gradient(0.5f, 0.0f), 0.0f);    // stratus is thin: nothing at mid-height
}

TEST(CloudDensity, StratusMassSitsLowerAndIsSmallerThanCumulonimbus) {
  const ProfileMoments stratus = profile_moments(0.0f), cumulus = profile_moments(0.5f), cumulonimbus = profile_moments(1.0f);
  EXPECT_LT(stratus.centroid, cumulus.centroid);
  EXPECT_LT(cumulus.centroid, cumulonimbus.centroid);
  EXPECT_LT(stratus.centroid, 0.15);
  EXPECT_GT(cumulonimbus.centroid, 0.35);
  EXPECT_LT(stratus.mass, cumulus.mass);
  EXPECT_LT(cumulus.mass, cumulonimbus.mass);
}

TEST(CloudDensity, CoverageZeroClearsEverythingAndCoverageOneKeepsTheBase) {
  const std::vector<float> steps = unit_steps(8);
  for (float r : steps) {
    for (float worley : steps) {
      for (float h : steps) {
        for (float type : {0.0f, 0.5f, 1.0f}) {
          const glm::vec4 shape(r, worley, 1.0f - worley, 0.5f);
          EXPECT_EQ(cloud_base_density(shape, h, 0.0f, type), 0.0f);
          // Schneider & Vos's base: r dilated by the Worley FBM, times the height gradient.
          const float fbm = 0.625f * shape.y + 0.25f * shape.z + 0.125f * shape.w;
          const float base = (r - (fbm - 1.0f)) / (2.0f - fbm) * cloud_height_gradient(h, type);
          EXPECT_NEAR(cloud_base_density(shape, h, 1.0f, type), base, 1e-6f) << r << " " << worley << " " << h;
          float previous = 0;
          for (float coverage : steps) {
            const float d = cloud_base_density(shape, h, coverage, type);
            EXPECT_GE(d, previous - 1e-6f) << "more coverage, no less cloud";
            EXPECT_LE(d, 1.0f);
            previous = d;
          }
        }
      }
    }
  }
  // Partial coverage clears the thin parts: a base below 1 − coverage reads 0.
  const glm::vec4 thin(0.1f, 0.0f, 0.0f, 0.0f);  // fbm 0: base (0.1 + 1) / 2 = 0.55 × gradient
  EXPECT_EQ(cloud_base_density(thin, 0.3f, 0.3f, 0.5f), 0.0f);
  EXPECT_GT(cloud_base_density(thin, 0.3f, 0.8f, 0.5f), 0.0f);
}

TEST(CloudDensity, ErosionNeverRaisesTheDensityNorMakesItNegative) {
  const std::vector<float> steps = unit_steps(10);
  for (float base : steps) {
    for (float detail : steps) {
      for (float h : steps) {
        const float d = cloud_eroded_density(base, glm::vec4(detail, 1.0f - detail, detail, 1.0f), h);
        EXPECT_GE(d, 0.0f) << base << " " << detail << " " << h;
        EXPECT_LE(d, base) << base << " " << detail << " " << h;
      }
    }
  }
  EXPECT_EQ(cloud_eroded_density(1.0f, glm::vec4(1.0f), 0.5f), 1.0f);  // the core is kept
  EXPECT_EQ(cloud_eroded_density(0.0f, glm::vec4(0.0f), 0.5f), 0.0f);
}

TEST(CloudDensity, TheDetailIsInvertedTowardTheBottom) {
  const glm::vec4 bright(1.0f), dark(0.0f);
  // Above a tenth of the layer a bright detail erodes a thin edge away and a dark one spares it…
  EXPECT_EQ(cloud_eroded_density(0.3f, bright, 0.5f), 0.0f);
  EXPECT_FLOAT_EQ(cloud_eroded_density(0.3f, dark, 0.5f), 0.3f);
  // …at the bottom the other way round.
  EXPECT_FLOAT_EQ(cloud_eroded_density(0.3f, bright, 0.0f), 0.3f);
  EXPECT_EQ(cloud_eroded_density(0.3f, dark, 0.0f), 0.0f);
}

TEST(CloudDensity, ExtinctionScalesWithDensityAndScatteringEqualsIt) {
  EXPECT_FLOAT_EQ(cloud_extinction(0.08f, 1.0f), 0.08f);
  EXPECT_FLOAT_EQ(cloud_extinction(0.08f, 0.25f), 0.02f);
  EXPECT_EQ(cloud_extinction(0.08f, 0.0f), 0.0f);
  for (float d : unit_steps(8)) EXPECT_EQ(cloud_scattering(0.05f, d), cloud_extinction(0.05f, d));
}

TEST(CloudDensity, EverythingIsFiniteOverTheWholeInputRange) {
  const std::vector<float> steps = unit_steps(4);
  for (float altitude : {-1e6f, 0.0f, 1500.0f, 4000.0f, 1e6f}) {
    ASSERT_TRUE(std::isfinite(cloud_height_fraction(altitude, 1500.0f, 4000.0f)));
    ASSERT_TRUE(std::isfinite(cloud_height_fraction(altitude, 1500.0f, 1500.0f))) << "a layer with no thickness";
  }
  for (float a : steps) {
    for (float b : steps) {
      for (float h : steps) {
        for (float coverage : steps) {
          for (float type : steps) {
            const float base = cloud_base_density(glm::vec4(a, b, a, b), h, coverage, type);
            ASSERT_TRUE(std::isfinite(base));
            ASSERT_GE(base, 0.0f);
            ASSERT_LE(base, 1.0f);
            const float eroded = cloud_eroded_density(base, glm::vec4(b, a, b, 0.0f), h);
            ASSERT_TRUE(std::isfinite(eroded));
            ASSERT_TRUE(std::isfinite(cloud_extinction(0.12f, eroded)));
            ASSERT_TRUE(std::isfinite(cloud_height_gradient(h, type)));
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace volgraph::physics
