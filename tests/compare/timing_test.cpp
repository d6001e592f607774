// Spreads of run times: the median of odd and even counts, the extremes.
#include "tools/compare/timing.h"

#include <gtest/gtest.h>

namespace volgraph::compare {
namespace {

TEST(Spread, OddCountMedianIsTheMiddleSample) {
  const Spread s = spread_of({5, 1, 3});
  EXPECT_EQ(s.median, 3);
  EXPECT_EQ(s.min, 1);
  EXPECT_EQ(s.max, 5);
  EXPECT_EQ(s.runs, 3);
}

TEST(Spread, EvenCountMedianIsTheMeanOfTheMiddleTwo) {
  EXPECT_EQ(spread_of({4, 1, 2, 10}).median, 3);
}

TEST(Spread, NoSamplesIsZero) { EXPECT_EQ(spread_of({}).runs, 0); }

}  // namespace
}  // namespace volgraph::compare
