#pragma once
// Every planner tandem has, by name: what it is, whether it takes an operator, the tunables it
// reads, and how to make one. The command line, scenario files, experiments, live sessions, the
// viewer and the conformance tests list planners from here; nothing else names them.
//
// Adding a planner: a file pair in planning/ (a Planner subclass) and one entry in
// planner_registry.cpp; its tunables, if new, in a ParamTable (see docs/architecture.md).

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tandem/interaction/interaction.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/sampling/guided_sampler.hpp"

namespace tandem {

/// The mixed portfolio: on several threads, RRT-Connect on even ones and goal-biased RRT on odd
/// ones (runs/portfolio.hpp); on one thread, RRT-Connect.
inline constexpr std::string_view kMixedPortfolio = "birrt+rrt";

/// What a planner is made from.
struct PlannerContext {
  MotionValidator& validator;
  const Config& start;
  const Config& goal;
  const PlannerSettings& settings;
  /// The operator; set exactly for the planners whose entry says uses_operator.
  const Interaction* interaction = nullptr;
  /// The workspace route from start to goal, found once for a run (a portfolio's members share
  /// it); null: a planner that follows it finds it.
  std::shared_ptr<const WorkspaceRoute> route = nullptr;
};

struct PlannerEntry {
  std::string_view name;
  std::string_view description;  ///< one line, for --help and the docs
  std::string_view citation;
  bool uses_operator = false;  ///< it needs an operator feed (and refuses to run without one)
  /// The groups of tunables it reads besides every tree planner's (ParamSpec::group).
  std::vector<std::string_view> groups;
  /// Its settings' defaults where they differ from PlannerSettings{} (e.g. contact on).
  void (*preset)(PlannerSettings&) = nullptr;
  std::unique_ptr<Planner> (*make)(const PlannerContext&) = nullptr;
  /// Whose range an OMPL.app problem's "<planner>.range" gives it.
  std::string_view ompl_range = "birrt";
};

const std::vector<PlannerEntry>& planner_registry();
/// The entry named `name`, or nullptr.
const PlannerEntry* find_planner(std::string_view name);
/// The registered names, in registry order.
std::vector<std::string> planner_names();
/// "unknown planner 'NAME' (known: birrt, rrt, ...)": the one message for a name not registered.
std::string unknown_planner(std::string_view name);

/// PlannerSettings{} with the planner's preset applied.
PlannerSettings default_settings(std::string_view name);

/// Makes the named planner. Throws std::invalid_argument for an unknown name, for an operator
/// given to a planner that cannot use one, and for none given to a planner that needs one.
std::unique_ptr<Planner> make_planner(std::string_view name, MotionValidator& validator,
                                      const Config& start, const Config& goal,
                                      const PlannerSettings& settings,
                                      const Interaction* interaction = nullptr);
/// The same, from everything a planner is made from.
std::unique_ptr<Planner> make_planner(std::string_view name, const PlannerContext& context);

/// Whether planner `name` reads the tunable.
bool planner_uses(std::string_view name, const ParamSpec& spec);

/// "interactive, interactive-contact": the registered planners that read the tunable.
std::string planner_users(const ParamSpec& spec);

}  // namespace tandem
