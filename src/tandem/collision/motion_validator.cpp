#include "tandem/collision/motion_validator.hpp"

#include <algorithm>
#include <cmath>

#include "tandem/core/error.hpp"

namespace tandem {
namespace {

/// A certified stretch is used a little short of its half-width c / L, so that neighbouring
/// stretches overlap instead of meeting at a point whose clearance is only known to be >= 0.
constexpr double kStretchShare = 0.999;
/// Head-room on L for the rounding of interpolate() (slerp turns at a constant rate only up to it).
constexpr double kRateMargin = 1e-9;

/// The largest clearance asked of FCL, in translation steps (the distance grid is asked for more).
constexpr double kCapSteps = 0.25;
/// The default tolerance, as a share of the bounds' diagonal. 1e-5 refused OMPL.app's own sample
/// solution of alpha-1.2, whose state 48 passes between 3e-3 and 6.6e-3 from the obstacle (the
/// diagonal is 665).
constexpr double kToleranceShare = 1e-6;
/// The most states (of the motion's steps: the end, then in bisection order) an exact check tries
/// with yes/no collision queries before it certifies the motion.
constexpr unsigned kCoarseStates = 8;
/// The distance grid's cells, in translation steps.
constexpr double kGridSteps = 0.5;

/// The clearance that certifies a stretch of the given half-width (as a share of the motion) on
/// either side of a configuration: no bound larger than it is needed, so FCL may stop there.
double needed_clearance(double rate, double half_width) {
  return 1.01 * rate * half_width / kStretchShare;
}

/// Calls visit(k) for the coarse states k of n steps other than the end, in bisection order
/// (n / 2, n / 4, 3n / 4, ...), until it returns true; whether it did.
template <class Visit>
bool any_coarse_step(unsigned n, Visit visit) {
  for (unsigned stride = n; stride > 1; stride /= 2) {
    for (unsigned k = stride / 2; k < n; k += stride) {
      if (visit(k))
        return true;
    }
  }
  return false;
}

/// Queues what is left of the stretch [s0, s1] on either side of mid once [mid - reach, mid +
/// reach] is certified.
void queue_rest(std::vector<std::pair<double, double>>& stretches, double s0, double s1, double mid,
                double reach) {
  if (mid - reach >= s0)
    stretches.emplace_back(s0, mid - reach);
  if (mid + reach <= s1)
    stretches.emplace_back(mid + reach, s1);
}

}  // namespace

MotionValidator::MotionValidator(const SE3Space& space, CollisionChecker& checker,
                                 const ValidationSettings& settings)
    : space_(space), checker_(checker) {
  configure(settings);
}

void MotionValidator::configure(const ValidationSettings& settings) {
  if (!(settings.tolerance >= 0.0) || !std::isfinite(settings.tolerance))
    throw InputError("tolerance", "must be a finite number >= 0");
  if (!(settings.clearance >= 0.0) || !std::isfinite(settings.clearance))
    throw InputError("clearance", "must be a finite number >= 0");
  if (settings.clearance > 0.0 && settings.mode != MotionValidation::exact)
    throw InputError("clearance", "needs exact validation (--validation exact)");
  mode_ = settings.mode;
  margin_ = settings.clearance;
  cache_.clear();
  tolerance_ =
      settings.tolerance > 0.0 ? settings.tolerance : kToleranceShare * space_.translation_extent();
  if (settings.distance_grid)
    checker_.use_distance_grid(space_.bounds(), kGridSteps * space_.translation_step());
  else
    checker_.drop_distance_grid();
  // The helper's clone takes the grid as it is now.
  if (helper_ != nullptr)
    helper_->set_checker(checker_.clone());
}

void MotionValidator::use_helper_thread() {
  helper_ = std::make_unique<QueryHelper>(checker_.clone());
}

template <class Query>
auto MotionValidator::counted(Query query) {
  ++checks_;
  if (!profiling_)
    return query();
  const Stopwatch watch;
  const auto answer = query();
  check_seconds_ += watch.seconds();
  return answer;
}

bool MotionValidator::collision_free(const Config& q) {
  return counted([&] { return checker_.is_collision_free(q); });
}

double MotionValidator::clearance(const Config& q, double cap) {
  // FCL's work grows with the cap (every pair of bounding volumes closer than it is opened): a
  // small cap costs less over a motion than certifying it in fewer, larger stretches. Without the
  // grid one step was best (Easy: 2.5 times less planning time than no limit). With it, a quarter
  // step (20 runs each, median: cubicles 0.23 s against 0.37 s at one step, 0.25 s at 0.1 and 0.5;
  // Maze_planar 0.59 against 0.93 s; Twistycool 12.7 against 18.2 s; Easy equal): the smaller
  // FCL's part, the more the grid answers alone. The grid's work hardly grows with the cap, so it
  // is asked for the whole of it.
  if (margin_ > 0.0)
    return clearance_beyond_margin(q, cap);
  // Named, not a structured binding: clang 14 (the fuzz build) refuses to capture one below.
  const std::pair<double, double> caps = clearance_caps(cap);
  const double full = caps.first;
  const double fcl_cap = caps.second;
  // A tree node's bound, known since it was added, serves every motion from it.
  if (const std::optional<double> known = cache_.find(q, fcl_cap))
    return std::min(*known, full);
  const double c = counted([&] { return checker_.clearance_bound(q, full, fcl_cap); });
  cache_.store(q, c, fcl_cap);
  return c;
}

std::pair<double, double> MotionValidator::clearance_caps(double cap) const {
  cap = std::max(cap, tolerance_);
  return {cap, std::max(std::min(cap, kCapSteps * space_.translation_step()), tolerance_)};
}

RoundQuery MotionValidator::clearance_query(const Config& q, double cap) const {
  const auto [full, fcl_cap] = clearance_caps(cap);
  return {.q = q, .cap = full, .fcl_cap = fcl_cap, .yes_no = false};
}

void MotionValidator::answer_round() {
  answers_.assign(round_.size(), 0.0);
  asked_.clear();
  asked_index_.clear();
  for (std::size_t i = 0; i < round_.size(); ++i) {
    const RoundQuery& r = round_[i];
    if (!r.yes_no) {
      if (const std::optional<double> known = cache_.find(r.q, r.fcl_cap)) {
        answers_[i] = std::min(*known, r.cap);
        continue;
      }
    }
    asked_.push_back(r);
    asked_index_.push_back(i);
  }
  replies_.resize(asked_.size());
  checks_ += asked_.size();
  const Stopwatch watch;
  helper_->run(asked_, replies_, checker_);
  if (profiling_)
    check_seconds_ += watch.seconds();
  for (std::size_t k = 0; k < asked_.size(); ++k) {
    answers_[asked_index_[k]] = replies_[k];
    if (!asked_[k].yes_no)
      cache_.store(asked_[k].q, replies_[k], asked_[k].fcl_cap);
  }
}

double MotionValidator::clearance_beyond_margin(const Config& q, double cap) {
  // The cap and FCL's window are counted beyond the margin.
  const double asked = std::max(cap, tolerance_);
  const double full = asked + margin_;
  const double window = margin_ + kCapSteps * space_.translation_step();
  const double fcl_cap = std::max(std::min(full, window), tolerance_ + margin_);
  double c = 0.0;
  if (const std::optional<double> known = cache_.find(q, fcl_cap)) {
    c = std::min(*known, full);
  } else {
    c = counted([&] { return checker_.clearance_bound(q, full, fcl_cap); });
    // Near the margin, FCL's relative error (up to 25%) would refuse what is far enough: the
    // exact distance there (FCL's nearest_obstacle, no error).
    if (c > 0.0 && c < window) {
      const NearestObstacle n = counted([&] { return checker_.nearest_obstacle(q); });
      c = n.in_collision ? 0.0 : std::max(c, std::min(n.distance, fcl_cap));
    }
    cache_.store(q, c, fcl_cap);
  }
  // Subtracting the margin may round below what was certified: nothing closer than the cap, or
  // than FCL's window (at least the tolerance beyond the margin), reads as that exactly.
  if (c >= full)
    return asked;
  if (c >= fcl_cap)
    return std::max(fcl_cap - margin_, tolerance_);
  return c - margin_;
}

double MotionValidator::displacement_rate(const Config& a, const Config& b) const {
  const double turn = SE3Space::rotation_angle(a.q, b.q);
  return ((a.t - b.t).norm() + turn * checker_.object_radius()) * (1.0 + kRateMargin);
}

bool MotionValidator::check_motion_discrete(const Config& a, const Config& b) {
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

bool MotionValidator::collides_coarsely(const Config& a, const Config& b) {
  const unsigned n = std::min(kCoarseStates, space_.segment_count(a, b));
  // The end first, then the others in bisection order (n / 2, n / 4, 3n / 4, ...).
  if (!collision_free(b))
    return true;
  return any_coarse_step(n, [&](unsigned k) { return !collision_free(space_.step(a, b, k, n)); });
}

bool MotionValidator::check_motion_exact(const Config& a, const Config& b) {
  if (helper_ != nullptr && margin_ == 0.0)
    return check_motion_in_rounds(a, b);
  const double rate = displacement_rate(a, b);
  if (!space_.satisfies_bounds(b)) {
    ++checks_;
    return false;
  }
  // 0. Most motions an RRT tries collide: a few yes/no queries (a fraction of a clearance query's
  //    cost each) turn most of them down before any clearance is asked for.
  if (collides_coarsely(a, b))
    return false;
  // 1. The end, then the start (a is valid, but how far it is from the obstacles is not known).
  const double c_b = clearance(b, needed_clearance(rate, 1.0));
  if (c_b < tolerance_)
    return false;
  if (!(rate > 0.0))
    return true;
  const double c_a = clearance(a, needed_clearance(rate, 1.0));
  // 2. What the two ends leave uncertified: [lo, hi].
  const double lo = std::max(0.0, c_a) / rate * kStretchShare;
  const double hi = 1.0 - c_b / rate * kStretchShare;
  stretches_.clear();
  if (lo <= hi)
    stretches_.emplace_back(lo, hi);
  // 3. Breadth-first bisection: the midpoint of each uncertified stretch certifies c / L either
  //    side of it; what is left of the stretch on either side is queued. Every query certifies at
  //    least 2 x 0.999 x tolerance / L, so this ends.
  for (std::size_t head = 0; head < stretches_.size(); ++head) {
    const auto [s0, s1] = stretches_[head];
    const double mid = 0.5 * (s0 + s1);
    const Config q = space_.interpolate(a, b, mid);
    if (!space_.satisfies_bounds(q)) {
      ++checks_;
      return false;
    }
    const double c = clearance(q, needed_clearance(rate, 0.5 * (s1 - s0)));
    if (c < tolerance_)
      return false;
    queue_rest(stretches_, s0, s1, mid, c / rate * kStretchShare);
  }
  return true;
}

bool MotionValidator::check_motion_in_rounds(const Config& a, const Config& b) {
  const double rate = displacement_rate(a, b);
  if (!space_.satisfies_bounds(b)) {
    ++checks_;
    return false;
  }
  // 0. The end alone (most motions tried end in collision), then the other coarse states.
  if (!collision_free(b))
    return false;
  const unsigned n = std::min(kCoarseStates, space_.segment_count(a, b));
  round_.clear();
  any_coarse_step(n, [&](unsigned k) {
    round_.push_back({.q = space_.step(a, b, k, n), .yes_no = true});
    return false;
  });
  answer_round();
  if (std::ranges::find(answers_, 0.0) != answers_.end())
    return false;
  // 1. The two ends' clearances, and the middle's: the bisection's first state, asked before
  //    the ends say whether it is needed.
  round_ = {clearance_query(b, needed_clearance(rate, 1.0))};
  if (!(rate > 0.0)) {
    answer_round();
    return answers_[0] >= tolerance_;
  }
  round_.push_back(clearance_query(a, needed_clearance(rate, 1.0)));
  round_.push_back(clearance_query(space_.interpolate(a, b, 0.5), needed_clearance(rate, 0.5)));
  answer_round();
  const double c_b = answers_[0];
  const double c_mid = answers_[2];
  if (c_b < tolerance_ || c_mid < tolerance_)
    return false;
  // 2. What the three leave uncertified: [lo, hi] less the middle's stretch.
  const double lo = std::max(0.0, answers_[1]) / rate * kStretchShare;
  const double hi = 1.0 - c_b / rate * kStretchShare;
  const double mid_reach = c_mid / rate * kStretchShare;
  stretches_.clear();
  if (lo <= std::min(hi, 0.5 - mid_reach))
    stretches_.emplace_back(lo, std::min(hi, 0.5 - mid_reach));
  if (std::max(lo, 0.5 + mid_reach) <= hi)
    stretches_.emplace_back(std::max(lo, 0.5 + mid_reach), hi);
  // 3. The bisection, a level of it per round: each stretch's midpoint, then what is left of the
  //    stretches on either side for the next level.
  for (std::size_t head = 0; head < stretches_.size();) {
    const std::size_t end = stretches_.size();
    round_.clear();
    for (std::size_t i = head; i < end; ++i) {
      const auto [s0, s1] = stretches_[i];
      const Config q = space_.interpolate(a, b, 0.5 * (s0 + s1));
      if (!space_.satisfies_bounds(q)) {
        ++checks_;
        return false;
      }
      round_.push_back(clearance_query(q, needed_clearance(rate, 0.5 * (s1 - s0))));
    }
    answer_round();
    if (std::ranges::any_of(answers_, [&](double c) { return c < tolerance_; }))
      return false;
    for (std::size_t i = head; i < end; ++i) {
      const auto [s0, s1] = stretches_[i];
      const double mid = 0.5 * (s0 + s1);
      queue_rest(stretches_, s0, s1, mid, answers_[i - head] / rate * kStretchShare);
    }
    head = end;
  }
  return true;
}

MotionCheck MotionValidator::last_valid_discrete(const Config& a, const Config& b) {
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

MotionCheck MotionValidator::last_valid_exact(const Config& a, const Config& b) {
  MotionCheck r;
  r.steps = space_.segment_count(a, b);
  r.last_valid = a;
  const double rate = displacement_rate(a, b);
  if (!(rate > 0.0)) {
    r.valid = is_valid(b);
    if (r.valid)
      r.last_valid = b;
    return r;
  }
  // Forward: from the last certified configuration at s with clearance c, the motion is free up
  // to s + c / L; the configuration there is queried next. The sweep stops in front of an
  // obstacle, at the first configuration closer than a tenth of a resolution step (as the discrete
  // sweep stops up to a step before it): closer, the steps would shrink with the clearance, and
  // nodes that close would make every later motion from them slow to certify (at the tolerance
  // itself, environment 1 planned 2000 times slower).
  const double stop = std::max(tolerance_, kSweepStopSteps * space_.translation_step());
  // Asked for at least `stop`: a bound capped below it (a short motion needs little) would read as
  // too close.
  const auto bound = [&](const Config& q, double rest) {
    return clearance(q, std::max(needed_clearance(rate, rest), stop));
  };
  double s = 0.0;
  double c = bound(a, 1.0);
  while (c >= stop) {
    const double next = s + c / rate * kStretchShare;
    if (next >= 1.0) {
      r.valid = is_valid(b);
      if (r.valid) {
        r.last_valid = b;
        r.last_valid_step = r.steps;
        return r;
      }
      break;
    }
    const Config q = space_.interpolate(a, b, next);
    if (!space_.satisfies_bounds(q))
      break;
    const double c_next = bound(q, 1.0 - next);
    if (c_next < stop)
      break;
    s = next;
    c = c_next;
    r.last_valid = q;
  }
  r.last_valid_step = static_cast<unsigned>(std::floor(s * r.steps));
  return r;
}

}  // namespace tandem
