// The portfolio (runs/portfolio.hpp): its winner is the member that solves with the least work
// (its collision queries' tests, query_work()), whatever the threads' timing, so a run is
// reproducible from its seed and thread count.

#include "tandem/runs/portfolio.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <limits>
#include <set>

#include "support/problems.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/runs/run_spec.hpp"

namespace tandem {
namespace {

RunSpec birrt_spec(std::uint64_t seed, unsigned threads, std::string_view mode = "birrt",
                   double guide = PlannerSettings{}.guide) {
  RunSpec spec = default_spec(mode, {});
  spec.mode = mode;
  spec.settings.guide = guide;
  spec.settings.seed = seed;
  spec.settings.threads = threads;
  spec.time_limit = 1e9;
  return spec;
}

/// Member i alone: the plain run of its planner with its seed.
RunOutcome alone(const Problem& problem, std::uint64_t seed, unsigned member,
                 std::string_view mode = "birrt", double guide = PlannerSettings{}.guide) {
  return execute_run(problem,
                     birrt_spec(member_seed(seed, member), 1, member_planner(mode, member), guide));
}

TEST(Portfolio, MemberZeroHasTheRunsSeedAndTheOthersDifferentOnes) {
  EXPECT_EQ(member_seed(42, 0), 42u);
  std::set<std::uint64_t> seeds;
  for (unsigned i = 0; i < 8; ++i)
    seeds.insert(member_seed(42, i));
  EXPECT_EQ(seeds.size(), 8u);
  EXPECT_EQ(member_seed(42, 5), member_seed(42, 5));
}

TEST(Portfolio, OneMemberIsThePlainRun) {
  const Problem problem = test::detour_problem();
  CollisionChecker checker(problem.scene);
  const RunOutcome plain = execute_run(problem, birrt_spec(7, 1));
  const RunOutcome one = run_portfolio(problem, birrt_spec(7, 1), checker, 1);
  ASSERT_EQ(plain.status, PlannerStatus::solved);
  EXPECT_EQ(one.status, PlannerStatus::solved);
  EXPECT_EQ(one.stats.iterations, plain.stats.iterations);
  EXPECT_EQ(one.stats.collision_checks, plain.stats.collision_checks);
  EXPECT_EQ(one.stats.work, plain.stats.work);
  EXPECT_EQ(one.tree_digest, plain.tree_digest);
}

/// For each seed: the member that solves with the least work, run alone, is the portfolio's
/// outcome, every time (the threads' timing differs from run to run, the winner does not).
void expect_the_least_work_wins(std::string_view mode, std::initializer_list<std::uint64_t> seeds,
                                std::set<unsigned>& winners,
                                double guide = PlannerSettings{}.guide) {
  const Problem problem = test::detour_problem();
  constexpr unsigned kThreads = 4;
  for (std::uint64_t seed : seeds) {
    SCOPED_TRACE(std::string(mode) + ", seed " + std::to_string(seed));
    std::uint64_t least = std::numeric_limits<std::uint64_t>::max();
    RunOutcome best;
    unsigned best_index = 0;
    for (unsigned i = 0; i < kThreads; ++i) {
      const RunOutcome o = alone(problem, seed, i, mode, guide);
      ASSERT_EQ(o.status, PlannerStatus::solved);
      if (o.stats.work < least) {
        least = o.stats.work;
        best = o;
        best_index = i;
      }
    }
    winners.insert(best_index);
    for (int repeat = 0; repeat < 3; ++repeat) {
      const RunOutcome o = execute_run(problem, birrt_spec(seed, kThreads, mode, guide));
      EXPECT_EQ(o.status, PlannerStatus::solved);
      EXPECT_EQ(o.threads, kThreads);
      EXPECT_EQ(o.member, best_index);
      EXPECT_EQ(o.stats.iterations, best.stats.iterations);
      EXPECT_EQ(o.tree_digest, best.tree_digest);
      ASSERT_FALSE(o.path.empty());
      EXPECT_EQ(o.path.front(), problem.start);
      EXPECT_EQ(o.path.back(), problem.goal);
    }
  }
}

TEST(Portfolio, TheWinnerIsTheMemberThatSolvesWithTheLeastWork) {
  std::set<unsigned> winners;
  expect_the_least_work_wins("birrt", {1, 2, 3}, winners);
  // The seeds are such that the winner is not always the same member.
  EXPECT_GT(winners.size(), 1u);
}

TEST(Portfolio, TheMixedPortfolioRunsRrtConnectAndRrtOnAlternateMembers) {
  EXPECT_EQ(member_planner(kMixedPortfolio, 0), "birrt");
  EXPECT_EQ(member_planner(kMixedPortfolio, 1), "rrt");
  EXPECT_EQ(member_planner(kMixedPortfolio, 2), "birrt");
  EXPECT_EQ(member_planner("rrt", 0), "rrt");
  // Without a workspace guide (the detour's part fits its route lengthwise, below).
  std::set<unsigned> winners;
  expect_the_least_work_wins(kMixedPortfolio, {1, 2, 5}, winners, 0.0);
  bool rrt_won = false, birrt_won = false;
  for (unsigned w : winners)
    (w % 2 == 0 ? birrt_won : rrt_won) = true;
  EXPECT_TRUE(rrt_won && birrt_won) << "the seeds are such that each kind of member wins once";
  // One thread: RRT-Connect, exactly.
  const Problem problem = test::detour_problem();
  EXPECT_EQ(execute_run(problem, birrt_spec(5, 1, kMixedPortfolio)).tree_digest,
            execute_run(problem, birrt_spec(5, 1)).tree_digest);
}

TEST(Portfolio, WhereTheRouteLeadsTheMixedPortfolioRunsRrtConnectOnEveryMember) {
  EXPECT_EQ(member_planner(kMixedPortfolio, 1, true), "birrt");
  EXPECT_EQ(member_planner(kMixedPortfolio, 3, true), "birrt");
  const Problem problem = test::detour_problem();
  CollisionChecker checker(problem.scene);
  MotionValidator(problem.space, checker);  // the distance grid, as a run builds it
  const auto leads = [&](const RunSpec& spec) {
    return route_leads(spec, run_route(problem, spec, checker).get());
  };
  EXPECT_TRUE(leads(birrt_spec(1, 4, kMixedPortfolio)));
  EXPECT_FALSE(leads(birrt_spec(1, 4, kMixedPortfolio, 0.0)));
  EXPECT_FALSE(leads(birrt_spec(1, 4, "rrt")));
  EXPECT_FALSE(leads(birrt_spec(1, 4)));  // the route, but every member is RRT-Connect anyway
  EXPECT_EQ(run_route(problem, birrt_spec(1, 4, "rrt"), checker), nullptr);
  std::set<unsigned> winners;
  for (std::uint64_t seed : {1u, 2u, 5u}) {
    // Member 0 without its helper thread from the start: RRT-Connect on every member.
    RunSpec spec = birrt_spec(seed, 4, kMixedPortfolio);
    spec.helper_work = 0;
    const RunOutcome mixed = execute_run(problem, spec);
    const RunOutcome birrt = execute_run(problem, birrt_spec(seed, 4));
    winners.insert(birrt.member);
    EXPECT_EQ(mixed.member_planner, "birrt");
    EXPECT_EQ(mixed.member, birrt.member);
    EXPECT_EQ(mixed.tree_digest, birrt.tree_digest);
    // Without the guide, the alternation.
    const RunOutcome unguided = execute_run(problem, birrt_spec(seed, 4, kMixedPortfolio, 0.0));
    EXPECT_EQ(unguided.member_planner, unguided.member % 2 == 0 ? "birrt" : "rrt");
  }
  // The seeds are such that an odd member wins: one that the alternation would make an RRT.
  EXPECT_TRUE(winners.count(1) > 0 || winners.count(3) > 0);
}

TEST(Portfolio, WhereTheRouteLeadsMemberZeroHasAHelperThreadAndMemberOneWaitsForIt) {
  const Problem problem = test::detour_problem();
  for (std::uint64_t seed : {1u, 2u, 5u}) {
    SCOPED_TRACE(seed);
    // The detour's searches end long before member 0 would release its helper.
    const RunSpec spec = birrt_spec(seed, 2, kMixedPortfolio);
    const RunOutcome helped = execute_run(problem, spec);
    ASSERT_EQ(helped.status, PlannerStatus::solved);
    EXPECT_EQ(helped.member, 0u);
    EXPECT_EQ(helped.threads, 2u);
    EXPECT_LT(helped.stats.work, spec.helper_work);
    // Its motions were checked in rounds, which ask other queries than one at a time: other work
    // than the plain member 0's, the same on every run.
    const RunOutcome plain = alone(problem, seed, 0);
    EXPECT_NE(helped.stats.work, plain.stats.work);
    for (int repeat = 0; repeat < 3; ++repeat) {
      const RunOutcome again = execute_run(problem, spec);
      EXPECT_EQ(again.tree_digest, helped.tree_digest);
      EXPECT_EQ(again.stats.work, helped.stats.work);
    }
    // Released after a third of that work: member 1 joins the race, and the run is reproducible.
    RunSpec early = spec;
    early.helper_work = helped.stats.work / 3;
    const RunOutcome first = execute_run(problem, early);
    ASSERT_EQ(first.status, PlannerStatus::solved);
    for (int repeat = 0; repeat < 3; ++repeat) {
      const RunOutcome again = execute_run(problem, early);
      EXPECT_EQ(again.member, first.member);
      EXPECT_EQ(again.tree_digest, first.tree_digest);
      EXPECT_EQ(again.stats.work, first.stats.work);
    }
  }
}

TEST(Portfolio, CountsEveryMembersCollisionChecks) {
  const Problem problem = test::detour_problem();
  const RunOutcome four = execute_run(problem, birrt_spec(3, 4));
  ASSERT_EQ(four.status, PlannerStatus::solved);
  std::uint64_t winners = 0;
  for (unsigned i = 0; i < 4; ++i) {
    const RunOutcome o = alone(problem, 3, i);
    if (o.tree_digest == four.tree_digest)
      winners = o.stats.collision_checks;
  }
  ASSERT_GT(winners, 0u);
  // The winner's own checks, and the other three's: each checked the start and the goal at least.
  EXPECT_GE(four.stats.collision_checks, winners + 3u * 2u);
}

TEST(Portfolio, WithoutASolutionShowsMemberZerosStatus) {
  const Problem closed = test::closed_problem();
  RunSpec spec = birrt_spec(1, 3);
  spec.max_iterations = 300;
  const RunOutcome o = execute_run(closed, spec);
  EXPECT_EQ(o.status, PlannerStatus::iteration_limit);
  EXPECT_EQ(o.stats.iterations, 300u);
  EXPECT_TRUE(o.path.empty());

  std::atomic<bool> stop{true};
  spec.stop = &stop;
  EXPECT_EQ(execute_run(closed, spec).status, PlannerStatus::interrupted);
}

TEST(Portfolio, AnInvalidStartIsTheOutcomeOfEveryMember) {
  Problem problem = test::detour_problem();
  problem.start.t = {0.0, -1.8, 0.0};  // inside wall-south
  const RunOutcome o = execute_run(problem, birrt_spec(1, 2));
  EXPECT_EQ(o.status, PlannerStatus::invalid_start);
}

}  // namespace
}  // namespace tandem
