// volume_visualize's transfer function and step opacity (shaders/include/volume_transfer.h,
// compiled as C++ by physics/volume_transfer.h) and the sphere phantom's ramp
// (physics/volume_phantom.h): the lookup equals the table exactly at every knot of every
// preset, is linear between knots, clamps outside them; the opacity correction is exact for
// the reference step and composes over split steps; nothing is NaN at the edges.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "physics/volume_phantom.h"
#include "physics/volume_transfer.h"

namespace volgraph::physics {
namespace {

using namespace volume_transfer;

void expect_exact_at_knots(const TransferTable& table) {
  for (int i = 0; i < table.count; ++i) {
    const float at = table.density[size_t(i)].x;
    if (i + 1 < table.count && table.density[size_t(i + 1)].x == at) continue;  // a step: the later knot holds there
    const glm::vec4 got = table(at), want = table.rgba[size_t(i)];
    for (int c = 0; c < 4; ++c) EXPECT_EQ(got[c], want[c]) << "knot " << i << " at density " << at << " channel " << c;
  }
}

TEST(VolumeTransfer, EveryPresetIsExactAtItsKnots) {
  expect_exact_at_knots(shells_transfer());
  expect_exact_at_knots(grey_transfer());
  expect_exact_at_knots(constant_transfer(glm::vec3(0.2f, 0.4f, 0.8f), 0.3f));
}

TEST(VolumeTransfer, LinearBetweenKnotsAndClampedOutside) {
  const TransferTable grey = grey_transfer();
  const glm::vec4 quarter = grey(0.25f);
  EXPECT_FLOAT_EQ(quarter.r, 0.25f);
  EXPECT_FLOAT_EQ(quarter.a, 0.0625f);
  const TransferTable shells = shells_transfer();
  const glm::vec4 between = shells(0.225f);  // halfway from the knot at 0.2 (transparent) to 0.25
  EXPECT_NEAR(between.b, 0.5f, 1e-6f) << "0.225 is not a float: the fraction rounds";
  EXPECT_NEAR(between.a, 0.02f, 1e-7f);
  EXPECT_EQ(grey(-1.0f), grey.rgba[0]);
  EXPECT_EQ(grey(2.0f), grey.rgba[1]);
  EXPECT_EQ(grey(std::numeric_limits<float>::quiet_NaN()), grey.rgba[0]) << "NaN reads the first knot";
}

TEST(VolumeTransfer, AStepOfTheReferenceLengthKeepsTheTablesOpacity) {
  for (const float alpha : {0.0f, 0.1f, 0.5f, 0.9f}) EXPECT_NEAR(volume_step_opacity(alpha, 0.02f, 0.02f), alpha, 1e-6f);
}

// (1 − α')² for two half steps equals 1 − α for one reference step: Engel et al. 2006 eq. 7.1.
TEST(VolumeTransfer, SplitStepsComposeToTheWholeStep) {
  for (const float alpha : {0.05f, 0.3f, 0.8f}) {
    const float half = volume_step_opacity(alpha, 0.5f, 1.0f);
    EXPECT_NEAR((1.0f - half) * (1.0f - half), 1.0f - alpha, 1e-6f) << alpha;
    const float thirds = volume_step_opacity(alpha, 1.0f / 3.0f, 1.0f);
    EXPECT_NEAR(std::pow(1.0f - thirds, 3.0f), 1.0f - alpha, 1e-6f) << alpha;
  }
}

TEST(VolumeTransfer, StepOpacityHasNoNaNAtTheEdges) {
  EXPECT_EQ(volume_step_opacity(1.0f, 0.0f, 1.0f), 0.0f) << "an empty step, even through an opaque table";
  EXPECT_EQ(volume_step_opacity(1.0f, 1e-9f, 1.0f), 1.0f);
  EXPECT_EQ(volume_step_opacity(0.5f, 1.0f, 0.0f), 0.0f) << "no reference length: nothing";
  EXPECT_EQ(volume_step_opacity(2.0f, 1.0f, 1.0f), 1.0f) << "opacity clamped to 1";
  EXPECT_FALSE(std::isnan(volume_step_opacity(0.5f, std::numeric_limits<float>::quiet_NaN(), 1.0f)));
  EXPECT_FALSE(std::isnan(volume_step_opacity(0.999999f, 1e6f, 1e-6f)));
}

// The sphere phantom's ramp puts density ρ exactly on the sphere of volume_sphere_iso_radius(ρ).
// The 2D transfer (density × gradient magnitude): off (gradient_high 0) the table's value
// exactly; the opacity × 0 below gradient_low, × 1 from gradient_high, linear between; the
// colour untouched.
TEST(VolumeTransfer, TheGradientRampScalesOnlyTheOpacity) {
  const vec4 table(0.2f, 0.4f, 0.6f, 0.5f);
  EXPECT_EQ(volume_transfer_2d(table, 3.0f, 1.0f, 0.0f), table);
  EXPECT_EQ(volume_transfer_2d(table, 0.5f, 1.0f, 2.0f), vec4(0.2f, 0.4f, 0.6f, 0.0f));
  EXPECT_EQ(volume_transfer_2d(table, 2.5f, 1.0f, 2.0f), table);
  EXPECT_EQ(volume_transfer_2d(table, 1.5f, 1.0f, 2.0f), vec4(0.2f, 0.4f, 0.6f, 0.25f));
  EXPECT_EQ(volume_transfer_2d(table, std::numeric_limits<float>::quiet_NaN(), 1.0f, 2.0f).w, 0.0f);
}

// The full 2D table (Kniss et al. 2002): every sample (i/(W − 1), j/(H − 1)·gradient_max) reads
// its texel exactly (W − 1 = 4, H − 1 = 2: the positions are whole in float); halfway between
// two samples the mean; outside the table its edge; NaN the first texel.
TEST(VolumeTransfer, TheTwoDimensionalTableIsExactAtItsSamples) {
  TransferTable2d table;
  table.width = 5, table.height = 3, table.gradient_max = 6.0f;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 5; ++i) table.rgba.push_back(vec4(float(i) / 7.0f, float(j) / 3.0f, float(i * j) / 11.0f, 0.1f + 0.2f * float(i)));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 5; ++i) EXPECT_EQ(table(float(i) / 4.0f, float(j) * 3.0f), table.texel(i, j)) << i << ", " << j;
  EXPECT_EQ(table(0.125f, 0.0f), 0.5f * (table.texel(0, 0) + table.texel(1, 0)));
  EXPECT_EQ(table(2.0f, 100.0f), table.texel(4, 2)) << "clamped to the table";
  EXPECT_EQ(table(std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::quiet_NaN()), table.texel(0, 0));
}

TEST(VolumePhantom, TheSpheresIsosurfacesAreSpheresOfKnownRadius) {
  using namespace volume_phantom;
  for (const float iso : {0.2f, 0.5f, 0.8f}) {
    const float r = volume_sphere_iso_radius(iso, 0.35f, 0.1f);
    for (const glm::vec3 direction : {glm::vec3(1, 0, 0), glm::normalize(glm::vec3(1, -2, 0.5f))})
      EXPECT_NEAR(volume_sphere_density(glm::vec3(0.5f) + r * direction, 0.35f, 0.1f), iso, 1e-6f) << iso;
  }
  EXPECT_EQ(volume_sphere_density(glm::vec3(0.5f), 0.35f, 0.1f), 1.0f);
  EXPECT_EQ(volume_sphere_density(glm::vec3(0.0f), 0.35f, 0.1f), 0.0f);
  EXPECT_EQ(volume_shells_density(glm::vec3(0.5f), 0.35f, 0.1f), float(VOLUME_SHELL_CORE_DENSITY));
}

}  // namespace
}  // namespace volgraph::physics
