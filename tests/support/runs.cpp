#include "support/runs.hpp"

#include "tandem/collision/collision_checker.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem::test {

PlanRun plan(const Problem& problem, const std::string& planner_name, std::uint64_t seed,
             double time_limit) {
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  PlannerSettings settings;
  settings.seed = seed;
  if (auto it = problem.hints.range.find(planner_name); it != problem.hints.range.end())
    settings.range = it->second;
  auto planner = make_planner(planner_name, validator, problem.start, problem.goal, settings);
  Termination t;
  t.time_limit_s = time_limit;
  PlanRun r{planner->solve(t), planner->stats()};
  if (r.status == PlannerStatus::solved) {
    CollisionChecker fresh(problem.scene);
    MotionValidator check(problem.space, fresh);
    r.path_valid = check_path(planner->solution(), check).valid;
  }
  return r;
}

RunSpec live_spec(std::uint64_t seed) {
  RunSpec spec = default_spec("interactive-contact", {});
  spec.settings.seed = seed;
  spec.settings.extend = ExtendMode::last_valid;
  spec.settings.interaction.alpha = 0.3;
  spec.operator_name = "experienced";
  spec.operator_seed = seed;
  spec.time_limit = 20.0;
  return spec;
}

ExperimentFixture::ExperimentFixture() {
  Config mid;
  mid.t = {0.0, 0.0, 0.0};
  problem.guide = {problem.start, mid, problem.goal};
  experiment = parse_experiment(R"(
name = "gap"
problem = "wall-with-gap"
seeds = 3
time_limit = 30
[[sweep]]
mode = ["birrt", "interactive-contact"]
[report]
rows = "mode"
)",
                                "gap.toml", ".");
}

}  // namespace tandem::test
