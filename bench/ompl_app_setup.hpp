#pragma once
// OMPL's side of the benchmark, set up as OMPL.app 1.5 sets up a rigid-body problem
// (app::SE3RigidBodyPlanning / SE2RigidBodyPlanning with its FCLStateValidityChecker), written
// here from OMPL and FCL directly. Nothing of tandem's collision checking or motion validation is
// used: tandem's loader only provides the meshes, start, goal, bounds, resolution and range hints.
//
// - Collision model: one fcl::BVHModel<OBBRSSd> for the whole environment (every triangle of every
//   obstacle part, in the world frame) and one for the robot (every triangle of the object's
//   parts, in the object frame), each triangle with three vertices of its own (OMPL.app's
//   triangle soup).
// - Validity: si->satisfiesBounds(state), then fcl::collide of the robot at the state against the
//   environment with a default CollisionRequestd (one contact, no contact data). Thread-safe: each
//   call has its own request and result; the BVH models are read-only and shared.
// - Space: SE3StateSpace (SE2StateSpace for planar problems) with the problem's bounds, OMPL's
//   default metric and default projection, DiscreteMotionValidator at the problem's resolution.
// - Planners: OMPL's defaults, except the range where the problem's [planner] section gives one
//   for that planner (as OMPL.app's benchmark does).

#include <ompl/base/Planner.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/tools/multiplan/ParallelPlan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "run_result.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/scene/problem.hpp"

namespace bench {

class FclValidityChecker;

/// A problem as OMPL.app sets it up: the space information with OMPL.app's validity checker.
class OmplAppProblem {
 public:
  /// Throws InputError if a part of the scene is not a triangle mesh.
  explicit OmplAppProblem(const tandem::Problem& problem);

  const ompl::base::SpaceInformationPtr& space_information() const { return si_; }
  bool planar() const { return planar_; }
  /// OMPL state validity checks so far (every planner and path check on this problem).
  std::uint64_t validity_checks() const;

  /// The OMPL state of a tandem configuration.
  ompl::base::ScopedState<> state(const tandem::Config& q) const;
  /// A problem definition from the problem's start to its goal.
  ompl::base::ProblemDefinitionPtr problem_definition() const;
  /// Whether OMPL accepts the path: og::PathGeometric::check(), i.e. the first state valid and
  /// every motion valid for OMPL's DiscreteMotionValidator.
  bool check_path(const tandem::Path& path) const;

 private:
  bool planar_;
  tandem::Config start_, goal_;
  ompl::base::SpaceInformationPtr si_;
  std::shared_ptr<FclValidityChecker> checker_;
};

/// The OMPL planners of --planners, in the order of the help text.
const std::vector<std::string>& ompl_planner_names();

/// The range the problem's [planner] section gives OMPL planner `name`, if any. tandem's loader
/// keeps rrtconnect.range (as hints.range["birrt"]) and rrt.range; only the first names a planner
/// run here (RRTConnect, also the parallel one); OMPL.app gives rrt.range to its RRT only.
std::optional<double> cfg_range(const tandem::Problem& problem, const std::string& name);

/// One OMPL planner on one problem: allocated and set up once, cleared before each run.
class OmplPlannerRunner {
 public:
  /// `name` is one of ompl_planner_names(); `threads` is used by prrt and parallel-rrtconnect.
  OmplPlannerRunner(const OmplAppProblem& problem, const std::string& name, unsigned threads,
                    std::optional<double> range);

  /// "ompl-" + the name.
  const std::string& label() const { return label_; }
  RunResult run(double time_limit);

 private:
  const OmplAppProblem& problem_;
  std::string label_;
  unsigned threads_ = 1;
  ompl::base::ProblemDefinitionPtr pdef_;
  /// One planner, or `threads` RRTConnects run by ParallelPlan.
  std::vector<ompl::base::PlannerPtr> planners_;
  std::unique_ptr<ompl::tools::ParallelPlan> parallel_;
  std::function<double()> range_;
};

}  // namespace bench
