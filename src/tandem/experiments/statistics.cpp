#include "tandem/experiments/statistics.hpp"

#include <algorithm>
#include <cmath>

namespace tandem {

Interval median_interval(std::vector<double> values, double z) {
  Interval r;
  const std::size_t n = values.size();
  if (n == 0)
    return r;
  std::sort(values.begin(), values.end());
  r.value = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  // 1-based ranks j and k of the interval's ends.
  const double half = z * std::sqrt(static_cast<double>(n)) / 2.0;
  const double j = std::floor(static_cast<double>(n) / 2.0 - half);
  const double k = std::ceil(static_cast<double>(n) / 2.0 + 1.0 + half);
  if (j >= 1.0 && k <= static_cast<double>(n)) {
    r.low = values[static_cast<std::size_t>(j) - 1];
    r.high = values[static_cast<std::size_t>(k) - 1];
    r.has_interval = true;
  }
  return r;
}

Interval success_interval(std::size_t successes, std::size_t n, double z) {
  Interval r;
  if (n == 0)
    return r;
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(successes) / nn;
  const double z2 = z * z;
  const double centre = (p + z2 / (2.0 * nn)) / (1.0 + z2 / nn);
  const double spread = z / (1.0 + z2 / nn) * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn));
  r.value = p;
  r.low = std::max(0.0, centre - spread);
  r.high = std::min(1.0, centre + spread);
  r.has_interval = true;
  return r;
}

}  // namespace tandem
