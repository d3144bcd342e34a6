// The cost of one collision query, tandem's against OMPL.app's, on OMPL.app's problems.
//
// For each problem: `--states` configurations drawn uniformly in the bounds (seeded), then the same
// configurations through each query, timed as a whole (no clock read per query):
// - ompl-app: OMPL.app's validity check (bounds, then fcl::collide of one robot BVH against one
//   environment BVH), as bench/ompl_app_setup.cpp sets it up;
// - collide: tandem's CollisionChecker::is_collision_free;
// - clearance: tandem's CollisionChecker::clearance_bound capped at one resolution step (what the
//   exact motion validation asks);
// - distance: tandem's CollisionChecker::nearest_obstacle (exact distance, nearest points).
// Also on "near" configurations: free ones within two resolution steps of an obstacle, where a
// planner's queries concentrate. Agreement between OMPL.app's and tandem's yes/no is checked.
//
//   build/bench/tandem-check-costs --shared ../shared --states 20000

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "ompl_app_setup.hpp"
#include "parse_arguments.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/rng.hpp"
#include "tandem/scene/ompl_app_problem.hpp"

namespace fs = std::filesystem;

namespace {

/// Microseconds per call of `query` over `states`.
double time_per_query(const std::vector<tandem::Config>& states,
                      const std::function<void(const tandem::Config&)>& query) {
  if (states.empty())
    return 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const tandem::Config& q : states)
    query(q);
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::micro>(t1 - t0).count() /
         static_cast<double>(states.size());
}

struct Sets {
  std::vector<tandem::Config> all, near;
};

Sets draw_states(const tandem::Problem& problem, tandem::CollisionChecker& checker, int count,
                 std::uint64_t seed) {
  tandem::Rng rng(seed);
  Sets s;
  const double near = 2.0 * problem.space.translation_step();
  while (static_cast<int>(s.all.size()) < count)
    s.all.push_back(problem.space.sample_uniform(rng));
  // Near configurations: random ones until as many as a tenth of `count` (or 50 * count tries).
  for (long tries = 0; static_cast<int>(s.near.size()) < count / 10 && tries < 50L * count;
       ++tries) {
    tandem::Config q = problem.space.sample_uniform(rng);
    const double c = checker.clearance_bound(q, near);
    if (c > 0.0 && c < near)
      s.near.push_back(q);
  }
  return s;
}

void measure(const std::string& name, const fs::path& cfg, int count, std::uint64_t seed) {
  const tandem::Problem problem = tandem::load_ompl_app_problem(cfg);
  tandem::CollisionChecker checker(problem.scene);
  const bench::OmplAppProblem ompl(problem);
  const Sets sets = draw_states(problem, checker, count, seed);
  const auto& si = ompl.space_information();
  const double cap = problem.space.translation_step();

  int disagree = 0;
  for (const tandem::Config& q : sets.all) {
    const bool theirs = si->isValid(ompl.state(q).get());
    const bool ours = problem.space.satisfies_bounds(q) && checker.is_collision_free(q);
    disagree += theirs != ours ? 1 : 0;
  }
  volatile double sink = 0.0;
  tandem::CollisionChecker gridded = checker.clone();
  const auto t0 = std::chrono::steady_clock::now();
  gridded.use_distance_grid(problem.space.bounds(), 0.5 * cap);
  const double build_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const auto* set : {&sets.all, &sets.near}) {
    std::vector<ompl::base::ScopedState<>> converted;
    converted.reserve(set->size());
    for (const tandem::Config& q : *set)
      converted.push_back(ompl.state(q));
    std::size_t i = 0;
    const double t_ompl = time_per_query(*set, [&](const tandem::Config&) {
      sink = sink + (si->isValid(converted[i++].get()) ? 1.0 : 0.0);
    });
    const double t_collide = time_per_query(
        *set, [&](const tandem::Config& q) { sink = sink + checker.is_collision_free(q); });
    const double t_clear = time_per_query(
        *set, [&](const tandem::Config& q) { sink = sink + checker.clearance_bound(q, cap); });
    const double t_dist = time_per_query(
        *set, [&](const tandem::Config& q) { sink = sink + checker.nearest_obstacle(q).distance; });
    const double g_collide = time_per_query(
        *set, [&](const tandem::Config& q) { sink = sink + gridded.is_collision_free(q); });
    const double g_clear = time_per_query(
        *set, [&](const tandem::Config& q) { sink = sink + gridded.clearance_bound(q, cap); });
    std::printf(
        "%-15s %-5s %6zu  ompl-app %8.2f us  collide %8.2f us  clearance %8.2f us  "
        "distance %8.2f us | grid: collide %8.2f us  clearance %8.2f us\n",
        name.c_str(), set == &sets.all ? "all" : "near", set->size(), t_ompl, t_collide, t_clear,
        t_dist, g_collide, g_clear);
  }
  // The grid must never certify more than FCL's exact distance, nor "free" in a collision.
  int grid_wrong = 0;
  for (const auto* set : {&sets.all, &sets.near}) {
    for (const tandem::Config& q : *set) {
      const tandem::NearestObstacle exact = checker.nearest_obstacle(q);
      const double bound = gridded.clearance_bound(q, 10.0 * cap, 0.0);
      grid_wrong += bound > exact.distance || (exact.in_collision && gridded.is_collision_free(q));
    }
  }
  std::vector<double> free_distances;
  for (const tandem::Config& q : sets.all) {
    const tandem::NearestObstacle exact = checker.nearest_obstacle(q);
    if (!exact.in_collision)
      free_distances.push_back(exact.distance / cap);
  }
  std::sort(free_distances.begin(), free_distances.end());
  // Where the grid's time goes: the states it answers alone, and those it passes to FCL.
  std::vector<tandem::Config> answered, passed;
  for (const tandem::Config& q : sets.all) {
    const std::uint64_t before = gridded.counters().prefilter_answers;
    sink = sink + gridded.is_collision_free(q);
    (gridded.counters().prefilter_answers > before ? answered : passed).push_back(q);
  }
  for (const auto* part : {&answered, &passed}) {
    const double fcl_alone = time_per_query(
        *part, [&](const tandem::Config& q) { sink = sink + checker.is_collision_free(q); });
    const double with_grid = time_per_query(
        *part, [&](const tandem::Config& q) { sink = sink + gridded.is_collision_free(q); });
    std::printf(
        "%-15s collide on the %zu states the grid %s: FCL alone %.2f us, with the grid %.2f us\n",
        name.c_str(), part->size(), part == &answered ? "answers" : "passes on", fcl_alone,
        with_grid);
  }
  std::printf(
      "%-15s free %zu of %zu, median clearance %.2f steps; grid answers %.1f%% of collide\n",
      name.c_str(), free_distances.size(), sets.all.size(),
      free_distances.empty() ? 0.0 : free_distances[free_distances.size() / 2],
      100.0 * static_cast<double>(answered.size()) / static_cast<double>(sets.all.size()));
  std::printf(
      "%-15s yes/no disagreements between OMPL.app and tandem: %d of %zu; grid built in "
      "%.3f s, wrong answers %d\n",
      name.c_str(), disagree, sets.all.size(), build_s, grid_wrong);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The cost of one collision query, tandem's against OMPL.app's"};
  std::string shared = "../shared";
  std::vector<std::string> problems = {"Easy",      "cubicles", "Twistycool",  "alpha-1.5",
                                       "Apartment", "bugtrap",  "Maze_planar", "BugTrap_planar"};
  int states = 20000;
  std::uint64_t seed = 1;
  app.add_option("--shared", shared, "The shared folder holding benchmarks/omplapp")
      ->capture_default_str();
  app.add_option("--problems", problems, "OMPL.app problems")->capture_default_str();
  app.add_option("--states", states, "Random configurations per problem")
      ->check(CLI::Range(10, 10000000))
      ->capture_default_str();
  app.add_option("--seed", seed, "Seed of the configurations")->capture_default_str();
  if (const auto code = bench::parse_arguments(app, argc, argv, "tandem-check-costs"))
    return *code;
  try {
    const fs::path dir = fs::path(shared) / "benchmarks" / "omplapp";
    for (const std::string& name : problems) {
      fs::path cfg = dir / "3D" / (name + ".cfg");
      if (!fs::is_regular_file(cfg))
        cfg = dir / "2D" / (name + ".cfg");
      if (!fs::is_regular_file(cfg))
        throw tandem::InputError("--problems", "unknown problem '" + name + "' in " + dir.string());
      measure(name, cfg, states, seed);
    }
  } catch (const tandem::InputError& e) {
    std::fprintf(stderr, "tandem-check-costs: %s\n", e.what());
    return 2;
  }
  return 0;
}
