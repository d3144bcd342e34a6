#pragma once
// Summary statistics of repeated runs: medians with distribution-free confidence intervals, and
// success rates with Wilson intervals. The papers' tables report single runs; ours report these.

#include <cstddef>
#include <vector>

namespace tandem {

struct Interval {
  double value = 0.0;  ///< the point estimate (median, or success rate)
  double low = 0.0;
  double high = 0.0;
  bool has_interval = false;  ///< false when there are too few values for the confidence asked
};

/// The median of `values` and a confidence interval for it from order statistics (the binomial
/// method: ranks n/2 -+ z sqrt(n)/2, the normal approximation; about 95% for z = 1.96). Needs at
/// least 6 values for an interval at 95%. An empty input gives value 0 and no interval.
Interval median_interval(std::vector<double> values, double z = 1.96);

/// The success rate successes/n with its Wilson score interval.
Interval success_interval(std::size_t successes, std::size_t n, double z = 1.96);

}  // namespace tandem
