#include "ompl_app_setup.hpp"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/est/BiEST.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/kpiece/LBKPIECE1.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/pRRT.h>
#include <ompl/geometric/planners/sbl/SBL.h>

#include <atomic>
#include <map>
#include <stdexcept>

#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace bench {
namespace {

using Bvh = fcl::BVHModel<fcl::OBBRSSd>;

const tandem::TriangleMesh& mesh_of(const tandem::Part& part, const std::string& body) {
  const auto* shape = std::get_if<tandem::MeshShape>(&part.geometry);
  if (shape == nullptr || !shape->mesh) {
    throw tandem::InputError("body '" + body + "'",
                             std::string("a ") + tandem::geometry_kind(part.geometry) +
                                 " part: OMPL.app's collision model takes triangle meshes only");
  }
  return *shape->mesh;
}

/// One BVH of every triangle of the bodies' parts, each vertex posed by its part's pose (in the
/// bodies' frame: the world for obstacles, the object frame for the robot), three vertices per
/// triangle as OMPL.app's getFCLModelFromScene makes them.
std::shared_ptr<const Bvh> make_bvh(const std::vector<const tandem::Body*>& bodies) {
  std::vector<fcl::Vector3d> points;
  std::vector<fcl::Triangle> triangles;
  for (const tandem::Body* body : bodies) {
    for (const tandem::Part& part : body->parts) {
      const tandem::TriangleMesh& mesh = mesh_of(part, body->name);
      for (const auto& t : mesh.triangles) {
        const std::size_t first = points.size();
        for (const std::uint32_t v : t)
          points.push_back(part.pose * mesh.vertices.at(v));
        triangles.emplace_back(first, first + 1, first + 2);
      }
    }
  }
  auto model = std::make_shared<Bvh>();
  model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
  model->addSubModel(points, triangles);
  model->endModel();
  model->computeLocalAABB();
  return model;
}

}  // namespace

/// OMPL.app's FCLStateValidityChecker (one robot part, no self-collision), counting its calls.
class FclValidityChecker : public ob::StateValidityChecker {
 public:
  FclValidityChecker(const ob::SpaceInformationPtr& si, const tandem::Scene& scene, bool planar)
      : ob::StateValidityChecker(si), planar_(planar) {
    std::vector<const tandem::Body*> obstacles;
    for (const tandem::Body& body : scene.obstacles)
      obstacles.push_back(&body);
    environment_ = make_bvh(obstacles);
    robot_ = make_bvh({&scene.object});
  }

  bool isValid(const ob::State* state) const override {
    checks_.fetch_add(1, std::memory_order_relaxed);
    if (!si_->satisfiesBounds(state))
      return false;
    // The request and result are this call's own (OMPL.app's too), so threads do not share them.
    const fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    return fcl::collide(robot_.get(), robot_pose(state), environment_.get(),
                        fcl::Transform3d::Identity(), request, result) == 0;
  }

  std::uint64_t checks() const { return checks_.load(std::memory_order_relaxed); }

 private:
  /// OMPL.app's FCLPoseFromState: SE(3) as given; SE(2) at z = 0, rotated by the yaw about z.
  fcl::Transform3d robot_pose(const ob::State* state) const {
    if (planar_) {
      const auto* s = state->as<ob::SE2StateSpace::StateType>();
      return fcl::Translation3d(s->getX(), s->getY(), 0.0) *
             fcl::AngleAxisd(s->getYaw(), fcl::Vector3d::UnitZ());
    }
    const auto* s = state->as<ob::SE3StateSpace::StateType>();
    const auto& q = s->rotation();
    return fcl::Translation3d(s->getX(), s->getY(), s->getZ()) *
           fcl::Quaterniond(q.w, q.x, q.y, q.z);
  }

  bool planar_;
  std::shared_ptr<const Bvh> environment_;
  std::shared_ptr<const Bvh> robot_;
  mutable std::atomic<std::uint64_t> checks_{0};
};

namespace {

ob::StateSpacePtr make_space(const tandem::SE3Space& space) {
  const tandem::Bounds& b = space.bounds();
  const unsigned dims = space.planar() ? 2 : 3;
  ob::RealVectorBounds bounds(dims);
  for (unsigned i = 0; i < dims; ++i) {
    bounds.setLow(i, b.min[i]);
    bounds.setHigh(i, b.max[i]);
  }
  if (space.planar()) {
    auto se2 = std::make_shared<ob::SE2StateSpace>();
    se2->setBounds(bounds);
    return se2;
  }
  auto se3 = std::make_shared<ob::SE3StateSpace>();
  se3->setBounds(bounds);
  return se3;
}

void to_ompl(const tandem::Config& q, ob::State* state, bool planar) {
  if (planar) {
    auto* s = state->as<ob::SE2StateSpace::StateType>();
    s->setXY(q.t.x(), q.t.y());
    s->setYaw(tandem::SE3Space::yaw(q.q));
    return;
  }
  auto* s = state->as<ob::SE3StateSpace::StateType>();
  s->setXYZ(q.t.x(), q.t.y(), q.t.z());
  s->rotation().x = q.q.x();
  s->rotation().y = q.q.y();
  s->rotation().z = q.q.z();
  s->rotation().w = q.q.w();
}

}  // namespace

OmplAppProblem::OmplAppProblem(const tandem::Problem& problem)
    : planar_(problem.space.planar()), start_(problem.start), goal_(problem.goal) {
  si_ = std::make_shared<ob::SpaceInformation>(make_space(problem.space));
  checker_ = std::make_shared<FclValidityChecker>(si_, problem.scene, planar_);
  si_->setStateValidityChecker(checker_);
  si_->setStateValidityCheckingResolution(problem.space.resolution());
  si_->setup();  // the default DiscreteMotionValidator, the space's default projection
}

std::uint64_t OmplAppProblem::validity_checks() const {
  return checker_->checks();
}

ob::ScopedState<> OmplAppProblem::state(const tandem::Config& q) const {
  ob::ScopedState<> s(si_);
  to_ompl(q, s.get(), planar_);
  return s;
}

ob::ProblemDefinitionPtr OmplAppProblem::problem_definition() const {
  auto pdef = std::make_shared<ob::ProblemDefinition>(si_);
  pdef->setStartAndGoalStates(state(start_), state(goal_));
  return pdef;
}

bool OmplAppProblem::check_path(const tandem::Path& path) const {
  og::PathGeometric ompl_path(si_);
  for (const tandem::Config& q : path)
    ompl_path.append(state(q).get());
  return ompl_path.check();
}

namespace {

/// A planner and a way to read its range back after setup().
struct Allocated {
  ob::PlannerPtr planner;
  std::function<double()> range;
};

template <class P>
Allocated allocate(const ob::SpaceInformationPtr& si, std::optional<double> range) {
  auto planner = std::make_shared<P>(si);
  if (range)
    planner->setRange(*range);
  P* raw = planner.get();
  return {planner, [raw] { return raw->getRange(); }};
}

Allocated allocate(const std::string& name, const ob::SpaceInformationPtr& si, unsigned threads,
                   std::optional<double> range) {
  using Make = Allocated (*)(const ob::SpaceInformationPtr&, std::optional<double>);
  static const std::map<std::string, Make> kMakers = {
      {"rrtconnect", &allocate<og::RRTConnect>},
      {"parallel-rrtconnect", &allocate<og::RRTConnect>},
      {"kpiece1", &allocate<og::KPIECE1>},
      {"bkpiece1", &allocate<og::BKPIECE1>},
      {"lbkpiece1", &allocate<og::LBKPIECE1>},
      {"biest", &allocate<og::BiEST>},
      {"sbl", &allocate<og::SBL>},
      {"prrt", &allocate<og::pRRT>}};
  auto it = kMakers.find(name);
  if (it == kMakers.end())
    throw std::logic_error("OMPL planner '" + name + "' is not in the table");
  Allocated a = it->second(si, range);
  if (name == "prrt")
    std::static_pointer_cast<og::pRRT>(a.planner)->setThreadCount(threads);
  return a;
}

std::size_t vertex_count(const ob::Planner& planner) {
  ob::PlannerData data(planner.getSpaceInformation());
  planner.getPlannerData(data);
  return data.numVertices();
}

}  // namespace

const std::vector<std::string>& ompl_planner_names() {
  static const std::vector<std::string> kNames = {
      "rrtconnect", "kpiece1", "bkpiece1", "lbkpiece1",
      "biest",      "sbl",     "prrt",     "parallel-rrtconnect"};
  return kNames;
}

std::optional<double> cfg_range(const tandem::Problem& problem, const std::string& name) {
  if (name != "rrtconnect" && name != "parallel-rrtconnect")
    return std::nullopt;
  auto it = problem.hints.range.find("birrt");
  return it == problem.hints.range.end() ? std::nullopt : std::optional<double>(it->second);
}

OmplPlannerRunner::OmplPlannerRunner(const OmplAppProblem& problem, const std::string& name,
                                     unsigned threads, std::optional<double> range)
    : problem_(problem), label_("ompl-" + name), pdef_(problem.problem_definition()) {
  const auto& si = problem.space_information();
  const bool parallel = name == "parallel-rrtconnect";
  threads_ = parallel || name == "prrt" ? threads : 1;
  if (parallel)
    parallel_ = std::make_unique<ompl::tools::ParallelPlan>(pdef_);
  for (unsigned i = 0; i < (parallel ? threads : 1); ++i) {
    Allocated a = allocate(name, si, threads, range);
    a.planner->setProblemDefinition(pdef_);
    a.planner->setup();
    if (parallel)
      parallel_->addPlanner(a.planner);
    planners_.push_back(a.planner);
    range_ = a.range;
  }
}

RunResult OmplPlannerRunner::run(double time_limit) {
  for (const auto& planner : planners_)
    planner->clear();
  pdef_->clearSolutionPaths();
  RunResult r;
  r.planner = label_;
  r.threads = threads_;
  r.range = range_();
  const std::uint64_t checks_before = problem_.validity_checks();
  const ob::PlannerTerminationCondition ptc = ob::timedPlannerTerminationCondition(time_limit);
  const tandem::Stopwatch watch;
  // ParallelPlan without hybridization: the first solution stops every instance.
  const ob::PlannerStatus status =
      parallel_ ? parallel_->solve(ptc, 1, planners_.size(), false) : planners_[0]->solve(ptc);
  r.time_s = watch.seconds();
  r.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
  r.checks = problem_.validity_checks() - checks_before;
  for (const auto& planner : planners_)
    r.nodes += vertex_count(*planner);
  if (r.solved)
    r.path_length = pdef_->getSolutionPath()->length();
  return r;
}

}  // namespace bench
