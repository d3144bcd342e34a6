#pragma once
// Problems and fixtures that tests of several stages share: variants of the wall with a gap, a bar
// above a floor, a problem with its checker and validator, a simulated operator through the gap.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "support/test_support.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/interaction/operator_source.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/scene/problem.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem::test {

/// The wall with a gap, start and goal on either side away from the gap (the straight line between
/// them is blocked), and a guide through the gap: start, (-0.8, 0, 0), (0.8, 0, 0), goal.
Problem detour_problem();

/// The wall problem with the gap closed: unsolvable.
Problem closed_problem();

/// A 1 x 0.4 x 0.4 bar above a floor (top face at z = 0) and beside a wall (face at x = 2).
struct FloorScene {
  Problem problem;
  FloorScene() : problem(make()) {}
  static Problem make();
};

/// An SE(3) space with bounds [-5, 5] x [-5, 5] x [0, 2], for simulated operators.
const SE3Space& room_space();

/// A problem with its collision checker and motion validator.
struct ProblemFixture {
  explicit ProblemFixture(Problem p = wall_with_gap_problem()) : problem(std::move(p)) {}
  Problem problem;
  CollisionChecker checker{problem.scene};
  MotionValidator validator{problem.space, checker};

  /// A planner of the registry, without an operator.
  std::unique_ptr<Planner> planner(const std::string& name, PlannerSettings settings = {});
};

/// The detour problem and a simulated operator along its guide.
struct OperatorFixture : ProblemFixture {
  OperatorFixture() : ProblemFixture(detour_problem()) {}
  /// A GuideFollower along the problem's guide, on the planner-iteration clock.
  std::shared_ptr<const OperatorSource> operator_source(const std::string& profile = "experienced",
                                                        std::uint64_t seed = 1) const;
};

/// All nodes of all trees, in order.
std::vector<Config> all_nodes(const Planner& p);

}  // namespace tandem::test
