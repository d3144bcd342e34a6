// The statistics of an experiment's table: medians with their intervals, success rates.

#include "tandem/experiments/statistics.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tandem {
namespace {

TEST(Statistics, MedianIntervalFromOrderStatistics) {
  std::vector<double> v;
  for (int i = 20; i >= 1; --i)
    v.push_back(i);
  const Interval m = median_interval(v);
  EXPECT_DOUBLE_EQ(m.value, 10.5);
  ASSERT_TRUE(m.has_interval);
  // n = 20: ranks floor(10 - 1.96 sqrt(20) / 2) = 5 and ceil(11 + 4.38) = 16.
  EXPECT_DOUBLE_EQ(m.low, 5.0);
  EXPECT_DOUBLE_EQ(m.high, 16.0);
  const Interval few = median_interval({3.0, 1.0, 2.0});
  EXPECT_DOUBLE_EQ(few.value, 2.0);
  EXPECT_FALSE(few.has_interval);
  EXPECT_FALSE(median_interval({}).has_interval);
}

TEST(Statistics, WilsonIntervalOfASuccessRate) {
  const Interval none = success_interval(0, 10);
  EXPECT_DOUBLE_EQ(none.value, 0.0);
  EXPECT_DOUBLE_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 0.2775, 1e-3);
  const Interval all = success_interval(20, 20);
  EXPECT_NEAR(all.low, 0.8389, 1e-3);
  EXPECT_DOUBLE_EQ(all.high, 1.0);
}

}  // namespace
}  // namespace tandem
