#include "tandem/runs/portfolio.hpp"

#include <algorithm>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "tandem/core/rng.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/sampling/guided_sampler.hpp"

namespace tandem {
namespace {

/// Iterations a member runs between two looks at the race. One: a member that can no longer win
/// stops within an iteration of it (Easy is solved in a few dozen iterations, so 16 kept the
/// loser busy for up to half a solve), and a look (an uncontended lock) costs far less than an
/// iteration.
constexpr std::uint64_t kChunk = 1;

/// The best solved member so far, and whether the portfolio was abandoned (an error).
///
/// A member's work is its collision queries' (query_work(): the pairs of boxes and triangles
/// they tested, weighted), deterministic for its seed like its iterations, and a fair measure
/// across different planners: the queries are most of a search's time, and the work follows
/// their time where the number of queries did not (a clearance query costs several yes/no
/// queries, and an iteration of RRT-Connect makes more clearance queries than one of RRT). When
/// the losing member stopped only once its queries outnumbered the winner's, it ran on for a
/// median 1.6 ms (up to 6.7) after the winner solved on cubicles, whose runs take 24 ms; with
/// the work, cubicles' median went 24.4 -> 23.7 ms and its p90 30.1 -> 26.8 ms (README).
///
/// Threading: every member thread calls may_win() and offer(); the mutex guards all of it.
class Race {
 public:
  /// Whether member `index`, having done `work`, may still win: a solve with work w wins if w is
  /// below the best solve's, or equal to it with a lower index. Work never decreases.
  bool may_win(std::uint64_t work, unsigned index) const {
    const std::lock_guard lock(mutex_);
    return !abandoned_ && beats_best(work, index);
  }

  void offer(std::uint64_t work, unsigned index) {
    const std::lock_guard lock(mutex_);
    if (beats_best(work, index)) {
      solved_ = true;
      best_work_ = work;
      best_index_ = index;
    }
  }

  void abandon() {
    const std::lock_guard lock(mutex_);
    abandoned_ = true;
  }

  /// The winner's index, once every member has stopped; nullopt if none solved.
  std::optional<unsigned> winner() const {
    const std::lock_guard lock(mutex_);
    return solved_ ? std::optional<unsigned>(best_index_) : std::nullopt;
  }

 private:
  /// With the mutex held.
  bool beats_best(std::uint64_t work, unsigned index) const {
    return !solved_ || work < best_work_ || (work == best_work_ && index < best_index_);
  }

  mutable std::mutex mutex_;
  bool solved_ = false;
  bool abandoned_ = false;
  std::uint64_t best_work_ = 0;
  unsigned best_index_ = 0;
};

/// One search of the portfolio, with everything it owns.
struct Member {
  Member(const Problem& problem, const RunSpec& spec, const CollisionChecker& shared,
         unsigned index, const std::shared_ptr<const WorkspaceRoute>& route, bool helped)
      : name(member_planner(spec.mode, index, route_leads(spec, route.get()))),
        checker(shared.clone()),
        validator(problem.space, checker) {
    if (helped)
      validator.use_helper_thread();
    PlannerSettings settings = spec.settings;
    settings.seed = member_seed(spec.settings.seed, index);
    planner = make_planner(name, {.validator = validator,
                                  .start = problem.start,
                                  .goal = problem.goal,
                                  .settings = settings,
                                  .route = route});
  }

  std::string_view name;  ///< its planner
  CollisionChecker checker;
  MotionValidator validator;
  std::unique_ptr<Planner> planner;
  PlannerStatus status = PlannerStatus::running;
};

/// Runs a member in chunks until it solves, stops for its own reasons (time limit, interrupt,
/// iteration limit, invalid start or goal), or can no longer win. A helped member releases its
/// helper thread once its work reaches spec.helper_work, then calls `released`.
void run_member(Member& m, unsigned index, const RunSpec& spec, Race& race,
                const std::function<void()>& released) {
  Termination termination;
  termination.time_limit_s = spec.time_limit;
  termination.stop = spec.stop;
  for (;;) {
    const PlannerStats& stats = m.planner->stats();
    if (m.validator.has_helper_thread() && stats.work >= spec.helper_work) {
      m.validator.release_helper_thread();
      released();
    }
    if (stats.iterations >= spec.max_iterations || !race.may_win(stats.work, index)) {
      m.status = PlannerStatus::iteration_limit;
      return;
    }
    termination.max_iterations = std::min(kChunk, spec.max_iterations - stats.iterations);
    const PlannerStatus status = m.planner->solve(termination);
    if (status == PlannerStatus::solved)
      race.offer(m.planner->stats().work, index);
    if (status != PlannerStatus::iteration_limit) {
      m.status = status;
      return;
    }
  }
}

}  // namespace

std::uint64_t member_seed(std::uint64_t seed, unsigned index) {
  if (index == 0)
    return seed;
  Rng rng(seed);
  std::uint64_t s = seed;
  for (unsigned i = 0; i < index; ++i)
    s = rng.split();
  return s;
}

std::string_view member_planner(std::string_view mode, unsigned index, bool route_led) {
  if (mode == kMixedPortfolio)
    return index % 2 == 0 || route_led ? "birrt" : "rrt";
  return mode;
}

std::shared_ptr<const WorkspaceRoute> run_route(const Problem& problem, const RunSpec& spec,
                                                const CollisionChecker& checker) {
  if (!(spec.settings.guide > 0.0) || spec.mode == "rrt")
    return nullptr;
  return std::make_shared<const WorkspaceRoute>(
      workspace_route(problem.space, checker, problem.start.t, problem.goal.t));
}

bool route_leads(const RunSpec& spec, const WorkspaceRoute* route) {
  return spec.mode == kMixedPortfolio && route != nullptr && fits_lengthwise(*route);
}

unsigned resolve_threads(const RunSpec& spec) {
  if (spec.settings.threads != 0)
    return spec.settings.threads;
  return std::max(1u, std::thread::hardware_concurrency());
}

RunOutcome run_portfolio(const Problem& problem, const RunSpec& spec, CollisionChecker& checker,
                         unsigned threads) {
  // The distance grid once, before the clones that share it (not timed, as for one thread).
  MotionValidator(problem.space, checker, validation_settings(spec.settings));
  const Stopwatch wall;
  // Once for every member that follows it (each finding its own cost a route per member).
  const std::shared_ptr<const WorkspaceRoute> route = run_route(problem, spec, checker);
  // Where the route leads, member 0 starts with a helper thread, and member 1 starts when member 0
  // releases it.
  const bool helped = route_leads(spec, route.get());
  std::vector<std::unique_ptr<Member>> members;
  for (unsigned i = 0; i < threads; ++i)
    members.push_back(std::make_unique<Member>(problem, spec, checker, i, route, helped && i == 0));

  Race race;
  std::mutex error_mutex;
  std::exception_ptr error;
  std::vector<std::thread> pool;
  const auto run = [&](unsigned i, const std::function<void()>& released) {
    try {
      run_member(*members[i], i, spec, race, released);
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (!error)
        error = std::current_exception();
      race.abandon();
    }
  };
  // Member 0 on this thread. Waiting here in join() instead, after single-threaded work (loading,
  // the grid, a previous run), left a core idle while the last new thread queued behind a member
  // on the other core: Linux skips pulling work onto a core that was busy until just now
  // (sched_migration_cost), so on 2 cores the second member started up to 4 ms late (measured in
  // tandem-vs-ompl, whose OMPL runs are single-threaded).
  for (unsigned i = helped ? 2 : 1; i < threads; ++i)
    pool.emplace_back(run, i, std::function<void()>());
  run(0, [&] { pool.emplace_back(run, 1u, std::function<void()>()); });
  for (auto& t : pool)
    t.join();
  if (error)
    std::rethrow_exception(error);

  const unsigned shown = race.winner().value_or(0);
  const Member& m = *members[shown];
  RunOutcome outcome = planner_outcome(problem, *m.planner, m.status);
  outcome.stats.collision_checks = 0;
  outcome.stats.work = 0;
  outcome.stats.collision_time_s = 0.0;
  outcome.stats.nearest_time_s = 0.0;
  for (const auto& member : members) {
    const PlannerStats& s = member->planner->stats();
    outcome.stats.collision_checks += s.collision_checks;
    outcome.stats.work += s.work;
    outcome.stats.collision_time_s += s.collision_time_s;
    outcome.stats.nearest_time_s += s.nearest_time_s;
  }
  outcome.stats.time_s = wall.seconds();
  outcome.threads = threads;
  outcome.member = shown;
  outcome.member_planner = m.name;
  return outcome;
}

}  // namespace tandem
