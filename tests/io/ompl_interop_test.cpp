// OMPL reads tandem's path files: each line is loaded into an OMPL state by OMPL's own value layout
// (ScopedState's index order: x y z qx qy qz qw for SE(3), x y yaw for SE(2)), and OMPL's
// PathGeometric checks the path with its DiscreteMotionValidator at the same resolution.

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include "support/test_support.hpp"
#include "tandem/core/text.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

/// An OMPL SpaceInformation for the problem, whose validity checker is tandem's.
ob::SpaceInformationPtr ompl_space(const Problem& problem, MotionValidator& validator) {
  const auto& b = problem.space.bounds();
  const unsigned dims = problem.space.planar() ? 2 : 3;
  ob::RealVectorBounds bounds(dims);
  for (unsigned i = 0; i < dims; ++i) {
    bounds.setLow(i, b.min[static_cast<int>(i)]);
    bounds.setHigh(i, b.max[static_cast<int>(i)]);
  }
  ob::StateSpacePtr space;
  if (problem.space.planar()) {
    auto se2 = std::make_shared<ob::SE2StateSpace>();
    se2->setBounds(bounds);
    space = se2;
  } else {
    auto se3 = std::make_shared<ob::SE3StateSpace>();
    se3->setBounds(bounds);
    space = se3;
  }
  auto si = std::make_shared<ob::SpaceInformation>(space);
  const bool planar = problem.space.planar();
  si->setStateValidityChecker([&validator, &problem, planar](const ob::State* s) {
    Config q;
    if (planar) {
      const auto* p = s->as<ob::SE2StateSpace::StateType>();
      q = problem.space.planar_config(p->getX(), p->getY(), p->getYaw());
    } else {
      const auto* p = s->as<ob::SE3StateSpace::StateType>();
      q.t = {p->getX(), p->getY(), p->getZ()};
      q.q = Eigen::Quaterniond(p->rotation().w, p->rotation().x, p->rotation().y, p->rotation().z);
    }
    return validator.is_valid(q);
  });
  si->setStateValidityCheckingResolution(problem.space.resolution());
  si->setup();
  return si;
}

/// Loads a path file's lines into OMPL states by OMPL's value index.
og::PathGeometric ompl_path(const ob::SpaceInformationPtr& si, const std::string& text) {
  og::PathGeometric path(si);
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto fields = split_whitespace(line);
    if (fields.empty())
      continue;
    ob::ScopedState<> state(si->getStateSpace());
    EXPECT_EQ(fields.size(), si->getStateDimension() == 3 ? 3u : 7u);
    for (std::size_t i = 0; i < fields.size(); ++i)
      state[static_cast<unsigned>(i)] = *parse_double(fields[i]);
    path.append(state.get());
  }
  return path;
}

TEST(OmplInterop, OmplLoadsAndAcceptsTandemsPathOnTheBuiltinScene) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  const Problem problem = load_problem("cluttered-1");
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  PlannerSettings settings;
  settings.extend = ExtendMode::last_valid;
  auto planner = make_planner("birrt", validator, problem.start, problem.goal, settings);
  ASSERT_EQ(planner->solve(Termination{}), PlannerStatus::solved);
  const std::string text = format_path(planner->solution(), problem.space);

  auto si = ompl_space(problem, validator);
  og::PathGeometric path = ompl_path(si, text);
  ASSERT_EQ(path.getStateCount(), planner->solution().size());
  EXPECT_TRUE(path.check());
  // The same numbers arrive in OMPL's states.
  const auto* first = path.getState(0)->as<ob::SE3StateSpace::StateType>();
  EXPECT_DOUBLE_EQ(first->getX(), problem.start.t.x());
  EXPECT_DOUBLE_EQ(first->rotation().w, problem.start.q.w());
  EXPECT_NEAR(path.length(), path_length(problem.space, planner->solution()), 1e-9 * path.length());
}

TEST(OmplInterop, OmplRejectsAPathThroughAWall) {
  const Problem problem = test::wall_with_gap_problem();
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  auto si = ompl_space(problem, validator);
  EXPECT_FALSE(ompl_path(si, "-2 1 0 0 0 0 1\n2 1 0 0 0 0 1\n").check());
  EXPECT_TRUE(ompl_path(si, "-2 0 0 0 0 0 1\n2 0 0 0 0 0 1\n").check());
}

TEST(OmplInterop, PlanarPathsUseOmplsSE2Layout) {
  TANDEM_REQUIRE_SHARED_DATA();
  const Problem problem = load_problem(
      (test::shared_dir() / "benchmarks" / "omplapp" / "2D" / "Maze_planar.cfg").string());
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  auto planner = make_planner("birrt", validator, problem.start, problem.goal, PlannerSettings{});
  ASSERT_EQ(planner->solve(Termination{}), PlannerStatus::solved);
  auto si = ompl_space(problem, validator);
  og::PathGeometric path = ompl_path(si, format_path(planner->solution(), problem.space));
  EXPECT_TRUE(path.check());
  const auto* last = path.getState(static_cast<unsigned>(path.getStateCount() - 1))
                         ->as<ob::SE2StateSpace::StateType>();
  EXPECT_NEAR(last->getYaw(), SE3Space::yaw(problem.goal.q), 1e-12);
}

}  // namespace
}  // namespace tandem
