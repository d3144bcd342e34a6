#pragma once
// Order statistics for the benchmark's tables: the median and percentiles by nearest rank.

#include <vector>

namespace bench {

/// The median: the middle value, or the mean of the two middle values for an even count; NaN for
/// no values.
double median(std::vector<double> values);

/// The p-th percentile (0 < p <= 100) by nearest rank: the ceil(p / 100 * n)-th smallest value;
/// NaN for no values.
double percentile_nearest_rank(std::vector<double> values, double p);

/// The 90th percentile by nearest rank.
inline double p90(std::vector<double> values) {
  return percentile_nearest_rank(std::move(values), 90.0);
}

}  // namespace bench
