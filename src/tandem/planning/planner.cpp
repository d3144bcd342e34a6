#include "tandem/planning/planner.hpp"

#include <stdexcept>

#include "tandem/core/digest.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/planning/irrt.hpp"
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

std::string_view to_string(NodeSource source) {
  static constexpr std::string_view kNames[] = {"root", "random", "operator", "contact"};
  return kNames[static_cast<std::size_t>(source)];
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

std::string_view to_string(IrrtSampling mode) {
  static constexpr std::string_view kNames[] = {"mag", "path", "mag+cs", "path+cs"};
  return kNames[static_cast<std::size_t>(mode)];
}

std::optional<IrrtSampling> parse_irrt_sampling(std::string_view name) {
  for (auto m :
       {IrrtSampling::mag, IrrtSampling::path, IrrtSampling::mag_cs, IrrtSampling::path_cs}) {
    if (to_string(m) == name)
      return m;
  }
  return std::nullopt;
}

double contact_distance(const InteractionSettings& s, const SE3Space& space) {
  return s.contact_distance > 0.0 ? s.contact_distance : 0.015 * space.translation_extent();
}
double contact_clearance(const InteractionSettings& s, const SE3Space& space) {
  return s.contact_clearance > 0.0 ? s.contact_clearance : 0.1 * space.translation_step();
}
double sigma_translation(const InteractionSettings& s, const SE3Space& space) {
  return s.sigma > 0.0 ? s.sigma : 0.02 * space.translation_extent();
}

Planner::Planner(MotionValidator& validator, const Config& start, const Config& goal,
                 const PlannerSettings& settings, const Interaction* interaction)
    : validator_(validator),
      space_(validator.space()),
      start_(start),
      goal_(goal),
      settings_(settings),
      range_(settings.range > 0.0 ? settings.range : validator.space().default_range()),
      rng_(settings.seed) {
  if (interaction != nullptr) {
    if (interaction->feed == nullptr)
      throw std::invalid_argument("an Interaction needs an OperatorFeed");
    interaction_ = *interaction;
  }
  if (!(settings.goal_bias >= 0.0 && settings.goal_bias <= 1.0)) {
    throw std::invalid_argument("goal_bias must be in [0, 1]");
  }
}

const InteractionSettings& Planner::interaction_settings() {
  return interaction_.parameters != nullptr ? interaction_.parameters->latest()
                                            : settings_.interaction;
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
  stats_.operator_time_s =
      interaction_.feed != nullptr ? interaction_.feed->operator_seconds() : 0.0;
  stats_.operator_iterations = operator_iterations_;
  stats_.contact_entries = contact_entries_;
  stats_.extensions_collision =
      extension_outcomes_[static_cast<std::size_t>(ExtendStatus::trapped)];
  stats_.extensions_reached = extension_outcomes_[static_cast<std::size_t>(ExtendStatus::reached)];
  stats_.extensions_obstacle =
      extension_outcomes_[static_cast<std::size_t>(ExtendStatus::advanced)] +
      extension_outcomes_[static_cast<std::size_t>(ExtendStatus::stopped)];
  stats_.collision_checks = validator_.checks() - checks_at_start_;
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

std::unique_ptr<Planner> make_planner(std::string_view name, MotionValidator& validator,
                                      const Config& start, const Config& goal,
                                      const PlannerSettings& settings,
                                      const Interaction* interaction) {
  if (name == "birrt" || name == "rrtconnect")
    return std::make_unique<RRTConnect>(validator, start, goal, settings, interaction);
  if (name == "irrt")
    return std::make_unique<IRRT>(validator, start, goal, settings, interaction);
  if (name == "rrt")
    return std::make_unique<RRT>(validator, start, goal, settings);
  throw std::invalid_argument("unknown planner '" + std::string(name) + "'");
}

const std::vector<std::string>& planner_names() {
  static const std::vector<std::string> kNames = {"birrt", "rrt", "irrt"};
  return kNames;
}

}  // namespace tandem
