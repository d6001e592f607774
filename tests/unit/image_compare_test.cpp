// The golden-image metrics themselves: zero for equal images, one outlier for one
// broken pixel, NaN counted, and relative error scaled by the reference.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

std::vector<float> grey(size_t pixels, float v) {
  std::vector<float> rgba(4 * pixels, v);
  for (size_t p = 0; p < pixels; ++p) rgba[4 * p + 3] = 1;
  return rgba;
}

TEST(ImageCompare, EqualImagesDifferByNothing) {
  const ImageDifference d = compare_images(grey(100, 0.5f), grey(100, 0.5f));
  EXPECT_EQ(d.relative_mean_error, 0);
  EXPECT_EQ(d.outlier_fraction, 0);
  EXPECT_EQ(d.max_abs_error, 0);
}

TEST(ImageCompare, OneBrokenPixelIsOneOutlier) {
  std::vector<float> a = grey(100, 0.5f);
  a[4 * 7 + 1] = 0.6f;   // 20 % off in one channel: an outlier
  a[4 * 9 + 0] = 0.51f;  // 2 % off: not one
  const ImageDifference d = compare_images(a, grey(100, 0.5f));
  EXPECT_DOUBLE_EQ(d.outlier_fraction, 0.01);
  EXPECT_NEAR(d.max_abs_error, 0.1, 1e-6);
  EXPECT_NEAR(d.relative_mean_error, (0.1 + 0.01) / (300 * 0.5), 1e-7);
}

TEST(ImageCompare, NonFiniteValuesAreCountedAndOutliers) {
  std::vector<float> a = grey(10, 0.5f);
  a[0] = std::nanf("");
  a[5] = INFINITY;
  const ImageDifference d = compare_images(a, grey(10, 0.5f));
  EXPECT_EQ(d.non_finite, 2u);
  EXPECT_DOUBLE_EQ(d.outlier_fraction, 0.2);
}

TEST(ImageCompare, ImagesOfDifferentSizesAreRefused) {
  EXPECT_THROW(compare_images(grey(10, 0.5f), grey(11, 0.5f)), std::invalid_argument);
}

}  // namespace
}  // namespace volgraph::testing
