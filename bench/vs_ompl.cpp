// tandem's BiRRT against OMPL 1.5's RRTConnect, side by side on OMPL.app's problems.
//
// Fairness: both planners get the same problem (loaded once by tandem's OMPL.app loader), the same
// collision checker (tandem's FCL wrapper: OMPL's StateValidityChecker calls it), the same bounds
// test, the same motion resolution (OMPL's longestValidSegmentFraction = the problem's resolution)
// and the same range. Runs alternate between the planners (and which goes first), each with the
// same time limit, on one thread. OMPL keeps its own defaults otherwise (GNAT nearest neighbours,
// DiscreteMotionValidator).
//
// Output: a table per problem (success rates, median times with unsolved runs counted at the time
// limit, median collision checks, median time ratio tandem/OMPL), and one JSON line per run.

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/scene/ompl_app_problem.hpp"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

using tandem::Config;

struct RunResult {
  std::string planner;
  bool solved = false;
  double time_s = 0.0;
  std::uint64_t checks = 0;
  std::size_t nodes = 0;
  double path_length = 0.0;
  double collision_time_s = 0.0;
  double nearest_time_s = 0.0;
};

Config from_ompl(const ob::State* state, const tandem::SE3Space& space) {
  if (space.planar()) {
    const auto* s = state->as<ob::SE2StateSpace::StateType>();
    return space.planar_config(s->getX(), s->getY(), s->getYaw());
  }
  const auto* s = state->as<ob::SE3StateSpace::StateType>();
  Config q;
  q.t = {s->getX(), s->getY(), s->getZ()};
  const auto& r = s->rotation();
  q.q = Eigen::Quaterniond(r.w, r.x, r.y, r.z);
  return q;
}

void to_ompl(const Config& q, ob::State* state, const tandem::SE3Space& space) {
  if (space.planar()) {
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

/// OMPL's side: a SimpleSetup over the same space, validated by tandem's MotionValidator::is_valid.
class OmplSide {
 public:
  OmplSide(const tandem::Problem& problem, tandem::MotionValidator& validator, double range)
      : problem_(problem), validator_(validator) {
    const auto& b = problem.space.bounds();
    ob::StateSpacePtr space;
    if (problem.space.planar()) {
      auto se2 = std::make_shared<ob::SE2StateSpace>();
      ob::RealVectorBounds bounds(2);
      for (int i = 0; i < 2; ++i) {
        bounds.setLow(static_cast<unsigned>(i), b.min[i]);
        bounds.setHigh(static_cast<unsigned>(i), b.max[i]);
      }
      se2->setBounds(bounds);
      space = se2;
    } else {
      auto se3 = std::make_shared<ob::SE3StateSpace>();
      ob::RealVectorBounds bounds(3);
      for (int i = 0; i < 3; ++i) {
        bounds.setLow(static_cast<unsigned>(i), b.min[i]);
        bounds.setHigh(static_cast<unsigned>(i), b.max[i]);
      }
      se3->setBounds(bounds);
      space = se3;
    }
    setup_ = std::make_unique<og::SimpleSetup>(space);
    const tandem::SE3Space* tspace = &problem_.space;
    setup_->setStateValidityChecker(
        [this, tspace](const ob::State* s) { return validator_.is_valid(from_ompl(s, *tspace)); });
    setup_->getSpaceInformation()->setStateValidityCheckingResolution(problem.space.resolution());
    ob::ScopedState<> start(space), goal(space);
    to_ompl(problem.start, start.get(), problem.space);
    to_ompl(problem.goal, goal.get(), problem.space);
    setup_->setStartAndGoalStates(start, goal);
    auto planner = std::make_shared<og::RRTConnect>(setup_->getSpaceInformation());
    planner->setRange(range);
    setup_->setPlanner(planner);
    setup_->setup();
    range_ = planner->getRange();
    max_extent_ = space->getMaximumExtent();
  }

  double range() const { return range_; }
  double max_extent() const { return max_extent_; }

  RunResult run(double time_limit) {
    setup_->clear();
    const std::uint64_t before = validator_.checks();
    RunResult r;
    r.planner = "ompl-rrtconnect";
    const tandem::Stopwatch watch;
    const ob::PlannerStatus status =
        setup_->getPlanner()->solve(ob::timedPlannerTerminationCondition(time_limit));
    r.time_s = watch.seconds();
    r.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
    r.checks = validator_.checks() - before;
    ob::PlannerData data(setup_->getSpaceInformation());
    setup_->getPlanner()->getPlannerData(data);
    r.nodes = data.numVertices();
    if (r.solved) {
      tandem::Path path;
      for (const ob::State* s : setup_->getProblemDefinition()
                                    ->getSolutionPath()
                                    ->as<og::PathGeometric>()
                                    ->getStates()) {
        path.push_back(from_ompl(s, problem_.space));
      }
      r.path_length = tandem::path_length(problem_.space, path);
    }
    return r;
  }

 private:
  const tandem::Problem& problem_;
  tandem::MotionValidator& validator_;
  std::unique_ptr<og::SimpleSetup> setup_;
  double range_ = 0.0;
  double max_extent_ = 0.0;
};

RunResult run_tandem(const tandem::Problem& problem, tandem::MotionValidator& validator,
                     double range, std::uint64_t seed, double time_limit, bool profile,
                     tandem::ExtendMode extend) {
  tandem::PlannerSettings settings;
  settings.extend = extend;
  settings.seed = seed;
  settings.range = range;
  settings.profile = profile;
  auto planner = tandem::make_planner("birrt", validator, problem.start, problem.goal, settings);
  tandem::Termination t;
  t.time_limit_s = time_limit;
  const tandem::Stopwatch watch;
  const tandem::PlannerStatus status = planner->solve(t);
  RunResult r;
  r.planner = "tandem-birrt";
  r.time_s = watch.seconds();
  r.solved = status == tandem::PlannerStatus::solved;
  r.checks = planner->stats().collision_checks;
  r.nodes = planner->stats().nodes;
  r.collision_time_s = planner->stats().collision_time_s;
  r.nearest_time_s = planner->stats().nearest_time_s;
  if (r.solved)
    r.path_length = tandem::path_length(problem.space, planner->solution());
  return r;
}

double median(std::vector<double> v) {
  if (v.empty())
    return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tandem's BiRRT against OMPL's RRTConnect on OMPL.app problems, runs alternating"};
  std::string shared = "../shared";
  std::vector<std::string> problems = {"Easy",      "cubicles", "Twistycool", "alpha-1.5",
                                       "alpha-1.2", "bugtrap",  "Apartment"};
  int runs = 20;
  double time_limit = 60.0;
  std::uint64_t seed = 1;
  std::string jsonl;
  bool profile = false;
  std::string extend = "classic";
  app.add_option("--shared", shared, "The shared folder holding benchmarks/omplapp");
  app.add_option("--problems", problems, "OMPL.app 3D problem names")->delimiter(',');
  app.add_option("--runs", runs, "Runs per planner and problem")->check(CLI::PositiveNumber);
  app.add_option("--time-limit", time_limit, "Seconds per run (the problem's own limit if lower)")
      ->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "First seed; run i uses seed + i (OMPL is seeded once with it)");
  app.add_option("--jsonl", jsonl, "Also write one JSON line per run here");
  app.add_flag("--profile", profile,
               "Time tandem's collision checks and nearest-neighbour queries");
  app.add_option("--extend", extend, "tandem's extension: classic or last-valid")
      ->check(CLI::IsMember({"classic", "last-valid"}));
  CLI11_PARSE(app, argc, argv);

  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  ompl::RNG::setSeed(seed);
  std::ofstream lines;
  if (!jsonl.empty())
    lines.open(jsonl);

  std::printf("%-11s %5s %9s %9s %11s %11s %13s %13s %9s\n", "problem", "runs", "ok tandem",
              "ok OMPL", "t tandem s", "t OMPL s", "checks tandem", "checks OMPL", "t ratio");
  try {
    for (const std::string& name : problems) {
      const auto cfg =
          std::filesystem::path(shared) / "benchmarks" / "omplapp" / "3D" / (name + ".cfg");
      const tandem::Problem problem = tandem::load_ompl_app_problem(cfg);
      const double limit = std::min(time_limit, problem.hints.time_limit.value_or(time_limit));
      tandem::CollisionChecker checker(problem.scene);
      tandem::MotionValidator validator(problem.space, checker);
      const double range = problem.hints.range.count("birrt") ? problem.hints.range.at("birrt")
                                                              : problem.space.default_range();
      OmplSide ompl_side(problem, validator, range);
      if (std::abs(ompl_side.max_extent() - problem.space.max_extent()) >
              1e-9 * problem.space.max_extent() ||
          std::abs(ompl_side.range() - range) > 1e-12 * range) {
        throw std::logic_error("OMPL's space does not match tandem's for " + name);
      }
      std::map<std::string, std::vector<RunResult>> results;
      for (int i = 0; i < runs; ++i) {
        const bool tandem_first = i % 2 == 0;
        for (int turn = 0; turn < 2; ++turn) {
          RunResult r = (turn == 0) == tandem_first
                            ? run_tandem(problem, validator, range,
                                         seed + static_cast<std::uint64_t>(i), limit, profile,
                                         extend == "last-valid" ? tandem::ExtendMode::last_valid
                                                                : tandem::ExtendMode::classic)
                            : ompl_side.run(limit);
          if (lines.is_open()) {
            lines << nlohmann::json{{"problem", name},
                                    {"planner", r.planner},
                                    {"run", i},
                                    {"seed", seed + static_cast<std::uint64_t>(i)},
                                    {"solved", r.solved},
                                    {"time_s", r.time_s},
                                    {"collision_checks", r.checks},
                                    {"nodes", r.nodes},
                                    {"path_length", r.path_length},
                                    {"time_limit_s", limit},
                                    {"collision_time_s", r.collision_time_s},
                                    {"nearest_time_s", r.nearest_time_s}}
                         .dump()
                  << '\n'
                  << std::flush;
          }
          results[r.planner].push_back(std::move(r));
        }
      }
      auto summary = [&](const std::string& planner, int& ok, double& t, double& checks) {
        std::vector<double> times, counts;
        ok = 0;
        for (const auto& r : results[planner]) {
          ok += r.solved;
          times.push_back(r.solved ? r.time_s : limit);
          counts.push_back(static_cast<double>(r.checks));
        }
        t = median(times);
        checks = median(counts);
      };
      int ok_t, ok_o;
      double t_t, t_o, c_t, c_o;
      summary("tandem-birrt", ok_t, t_t, c_t);
      summary("ompl-rrtconnect", ok_o, t_o, c_o);
      std::printf("%-11s %5d %8d%% %8d%% %11.4f %11.4f %13.0f %13.0f %9.3f\n", name.c_str(), runs,
                  100 * ok_t / runs, 100 * ok_o / runs, t_t, t_o, c_t, c_o, t_t / t_o);
      if (profile) {
        double total = 0, coll = 0, nn = 0;
        for (const auto& r : results["tandem-birrt"]) {
          total += r.time_s;
          coll += r.collision_time_s;
          nn += r.nearest_time_s;
        }
        std::printf(
            "  tandem profile: collision checks %.1f%%, nearest neighbour %.1f%%, the rest "
            "%.1f%%\n",
            100 * coll / total, 100 * nn / total, 100 * (total - coll - nn) / total);
      }
      std::fflush(stdout);
    }
  } catch (const tandem::InputError& e) {
    std::cerr << "tandem-vs-ompl: error: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
