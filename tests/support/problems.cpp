#include "support/problems.hpp"

#include "tandem/operators/guide_follower.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem::test {

Problem detour_problem() {
  Problem p = wall_with_gap_problem();
  p.start.t = {-2, 2, 0};
  p.goal.t = {2, 2, 0};
  p.guide = {p.start, Config{}, Config{}, p.goal};
  p.guide[1].t = {-0.8, 0.0, 0.0};
  p.guide[2].t = {0.8, 0.0, 0.0};
  return p;
}

Problem closed_problem() {
  Problem p = wall_with_gap_problem();
  p.scene.obstacles.push_back(box_body("plug", {0.1, 0.8, 2.0}, {0, 0, 0}));
  return p;
}

Problem FloorScene::make() {
  Scene s;
  s.object.name = "bar";
  s.object.parts.push_back({Box{{1.0, 0.4, 0.4}}, Eigen::Isometry3d::Identity()});
  s.obstacles.push_back(box_body("floor", {10, 10, 0.2}, {0, 0, -0.1}));
  s.obstacles.push_back(box_body("wall", {0.2, 10, 4}, {2.1, 0, 2}));
  Config start, goal;
  start.t = {-2, 0, 1};
  goal.t = {1, 0, 1};
  return Problem{
      "floor",     "test", std::move(s), SE3Space(SpaceKind::se3, Bounds{{-3, -3, 0}, {1.8, 3, 2}}),
      start,       goal,   {},           {},
      std::nullopt};
}

const SE3Space& room_space() {
  static const SE3Space s(SpaceKind::se3, Bounds{{-5, -5, 0}, {5, 5, 2}});
  return s;
}

std::unique_ptr<Planner> ProblemFixture::planner(const std::string& name,
                                                 PlannerSettings settings) {
  return make_planner(name, validator, problem.start, problem.goal, settings);
}

std::shared_ptr<const OperatorSource> OperatorFixture::operator_source(const std::string& profile,
                                                                       std::uint64_t seed) const {
  return std::make_shared<GuideFollower>(
      problem.space, problem.guide, operator_profile(profile, problem.space, OperatorClock::ticks),
      seed);
}

std::vector<Config> all_nodes(const Planner& p) {
  std::vector<Config> out;
  for (const Tree* t : p.trees())
    out.insert(out.end(), t->nodes.begin(), t->nodes.end());
  return out;
}

}  // namespace tandem::test
