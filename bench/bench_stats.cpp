#include "bench_stats.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bench {

double median(std::vector<double> values) {
  if (values.empty())
    return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double percentile_nearest_rank(std::vector<double> values, double p) {
  if (!(p > 0.0 && p <= 100.0))
    throw std::invalid_argument("percentile_nearest_rank: p must be in (0, 100]");
  if (values.empty())
    return std::nan("");
  std::sort(values.begin(), values.end());
  const double n = static_cast<double>(values.size());
  // Rank 1 .. n; a tolerance keeps p/100 * n = 18.000000000000004 at rank 18.
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * n - 1e-9));
  return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

}  // namespace bench
