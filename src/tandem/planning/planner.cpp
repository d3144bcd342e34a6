#include "tandem/planning/planner.hpp"

#include <stdexcept>

#include "tandem/core/stopwatch.hpp"
#include "tandem/planning/rrt.hpp"
#include "tandem/planning/rrt_connect.hpp"

namespace tandem {

std::string_view to_string(PlannerStatus status) {
  switch (status) {
    case PlannerStatus::running:
      return "running";
    case PlannerStatus::solved:
      return "solved";
    case PlannerStatus::timeout:
      return "timeout";
    case PlannerStatus::iteration_limit:
      return "iteration_limit";
    case PlannerStatus::interrupted:
      return "interrupted";
    case PlannerStatus::invalid_start:
      return "invalid_start";
    case PlannerStatus::invalid_goal:
      return "invalid_goal";
  }
  return "unknown";
}

std::string_view to_string(ExtendMode mode) {
  return mode == ExtendMode::last_valid ? "last-valid" : "classic";
}

std::optional<ExtendMode> parse_extend_mode(std::string_view name) {
  if (name == "classic")
    return ExtendMode::classic;
  if (name == "last-valid")
    return ExtendMode::last_valid;
  return std::nullopt;
}

Planner::Planner(MotionValidator& validator, const Config& start, const Config& goal,
                 const PlannerSettings& settings)
    : validator_(validator),
      space_(validator.space()),
      start_(start),
      goal_(goal),
      settings_(settings),
      range_(settings.range > 0.0 ? settings.range : validator.space().default_range()),
      rng_(settings.seed) {
  if (!(settings.goal_bias >= 0.0 && settings.goal_bias <= 1.0)) {
    throw std::invalid_argument("goal_bias must be in [0, 1]");
  }
}

void Planner::update_counts() {
  stats_.nodes = 0;
  stats_.edges = 0;
  for (const Tree* t : trees()) {
    stats_.nodes += t->size();
    stats_.edges += t->size() - 1;
  }
  stats_.collision_checks = validator_.checks() - checks_at_start_;
  stats_.collision_time_s = validator_.check_seconds() - check_seconds_at_start_;
  stats_.nearest_time_s = nearest_seconds_;
}

void Planner::attach(Tree& tree) {
  if (settings_.profile)
    tree.profile_seconds = &nearest_seconds_;
}

PlannerStatus Planner::step() {
  if (status_ != PlannerStatus::running)
    return status_;
  if (!started_) {
    started_ = true;
    checks_at_start_ = validator_.checks();
    if (settings_.profile)
      validator_.set_profiling(true);
    check_seconds_at_start_ = validator_.check_seconds();
    if (!validator_.is_valid(start_))
      status_ = PlannerStatus::invalid_start;
    else if (!validator_.is_valid(goal_))
      status_ = PlannerStatus::invalid_goal;
    update_counts();
    if (status_ != PlannerStatus::running)
      return status_;
  }
  ++stats_.iterations;
  if (iterate())
    status_ = PlannerStatus::solved;
  update_counts();
  return status_;
}

PlannerStatus Planner::solve(const Termination& termination) {
  const Stopwatch watch;
  const double time_before = stats_.time_s;
  std::uint64_t steps = 0;
  while (status_ == PlannerStatus::running) {
    if (interrupt_requested_.exchange(false, std::memory_order_relaxed)) {
      stats_.time_s = time_before + watch.seconds();
      return PlannerStatus::interrupted;
    }
    const double elapsed = watch.seconds();
    if (time_before + elapsed >= termination.time_limit_s) {
      stats_.time_s = time_before + elapsed;
      return PlannerStatus::timeout;
    }
    if (steps++ >= termination.max_iterations) {
      stats_.time_s = time_before + elapsed;
      return PlannerStatus::iteration_limit;
    }
    step();
  }
  stats_.time_s = time_before + watch.seconds();
  return status_;
}

std::unique_ptr<Planner> make_planner(std::string_view name, MotionValidator& validator,
                                      const Config& start, const Config& goal,
                                      const PlannerSettings& settings) {
  if (name == "birrt" || name == "rrtconnect")
    return std::make_unique<RRTConnect>(validator, start, goal, settings);
  if (name == "rrt")
    return std::make_unique<RRT>(validator, start, goal, settings);
  throw std::invalid_argument("unknown planner '" + std::string(name) + "'");
}

const std::vector<std::string>& planner_names() {
  static const std::vector<std::string> kNames = {"birrt", "rrt"};
  return kNames;
}

}  // namespace tandem
