#include "tandem/planning/planner.hpp"

#include <stdexcept>

#include "tandem/core/digest.hpp"
#include "tandem/core/stopwatch.hpp"

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

std::uint64_t tree_digest(const std::vector<const Tree*>& trees) {
  Digest d;
  for (const Tree* tree : trees) {
    d.mix(tree->size());
    for (std::size_t i = 0; i < tree->size(); ++i) {
      d.mix_pose(tree->nodes[i]);
      d.mix(tree->parent[i]);
      d.mix(tree->source[i]);
    }
  }
  return d.value();
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
  validator.configure(validation_settings(settings));
}

void Planner::update_counts() {
  stats_.nodes = 0;
  stats_.edges = 0;
  stats_.nodes_by_source.fill(0);
  for (const Tree* t : trees()) {
    stats_.nodes += t->size();
    stats_.edges += t->size() - 1;
    for (std::size_t s = 0; s < kNodeSources; ++s)
      stats_.nodes_by_source[s] += t->by_source[s];
  }
  const SamplerStats sampler = sampler_stats();
  stats_.operator_time_s = sampler.operator_time_s;
  stats_.operator_iterations = sampler.operator_iterations;
  stats_.contact_entries = sampler.contact_entries;
  stats_.alpha = sampler.alpha;
  stats_.extensions_collision =
      extension_outcomes_[static_cast<std::size_t>(ExtendStatus::trapped)];
  stats_.extensions_reached = extension_outcomes_[static_cast<std::size_t>(ExtendStatus::reached)];
  stats_.extensions_obstacle =
      extension_outcomes_[static_cast<std::size_t>(ExtendStatus::advanced)] +
      extension_outcomes_[static_cast<std::size_t>(ExtendStatus::stopped)];
  stats_.collision_checks = validator_.checks() - checks_at_start_;
  stats_.work = validator_.work() - work_at_start_;
  stats_.collision_time_s = validator_.check_seconds() - check_seconds_at_start_;
  stats_.nearest_time_s = nearest_seconds_;
}

void Planner::count_extension(ExtendStatus status) {
  ++extension_outcomes_[static_cast<std::size_t>(status)];
}

double Planner::distance_to_roadmap(const Config& q) const {
  const Tree& tree = *trees().front();
  return space_.distance(q, tree.nodes[tree.nearest(q)]);
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
    work_at_start_ = validator_.work();
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
    if (interrupt_requested_.exchange(false, std::memory_order_relaxed) ||
        (termination.stop != nullptr && termination.stop->load(std::memory_order_relaxed))) {
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

}  // namespace tandem
