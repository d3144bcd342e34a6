#include "tandem/collision/motion_validator.hpp"

namespace tandem {

bool MotionValidator::check_motion(const Config& a, const Config& b) {
  if (!is_valid(b))
    return false;
  const unsigned n = space_.segment_count(a, b);
  if (n < 2)
    return true;
  // Breadth-first bisection over the open interval of steps [1, n-1].
  queue_.clear();
  queue_.emplace_back(1u, n - 1);
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const auto [lo, hi] = queue_[head];
    const unsigned mid = lo + (hi - lo) / 2;
    if (!is_valid(space_.step(a, b, mid, n)))
      return false;
    if (lo < mid)
      queue_.emplace_back(lo, mid - 1);
    if (hi > mid)
      queue_.emplace_back(mid + 1, hi);
  }
  return true;
}

MotionCheck MotionValidator::check_motion_last_valid(const Config& a, const Config& b) {
  MotionCheck r;
  r.steps = space_.segment_count(a, b);
  r.last_valid = a;
  if (r.steps == 0) {
    r.valid = is_valid(b);
    if (r.valid)
      r.last_valid = b;
    return r;
  }
  for (unsigned k = 1; k <= r.steps; ++k) {
    Config q = space_.step(a, b, k, r.steps);
    if (!is_valid(q))
      return r;
    r.last_valid = std::move(q);
    r.last_valid_step = k;
  }
  r.valid = true;
  return r;
}

}  // namespace tandem
