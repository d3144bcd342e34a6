// QueryHelper (collision/query_helper.hpp): a round of queries answered on two threads gives the
// answers and the work of the same queries answered one by one on one thread. Run again under
// ThreadSanitizer by scripts/test.

#include "tandem/collision/query_helper.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/problems.hpp"
#include "tandem/core/rng.hpp"

namespace tandem {
namespace {

/// Rounds of 0 to 12 random queries, clearance and yes/no mixed, on the detour problem.
std::vector<std::vector<RoundQuery>> random_rounds(const Problem& p, int count) {
  Rng rng(3);
  std::vector<std::vector<RoundQuery>> rounds(static_cast<std::size_t>(count));
  for (std::size_t r = 0; r < rounds.size(); ++r) {
    for (std::size_t i = 0; i < r % 13; ++i) {
      const double cap = rng.uniform(0.01, 1.0);
      rounds[r].push_back({.q = p.space.sample_uniform(rng),
                           .cap = cap,
                           .fcl_cap = cap * rng.uniform(0.1, 1.0),
                           .yes_no = rng.uniform01() < 0.3});
    }
  }
  return rounds;
}

/// Runs `round` through the helper (with `own` on this thread) and expects every answer to be
/// the reference checker's, asked one query at a time; returns how many said free.
int expect_answers_as_alone(QueryHelper& helper, const std::vector<RoundQuery>& round,
                            CollisionChecker& own, CollisionChecker& reference) {
  std::vector<double> answers(round.size(), -1.0);
  helper.run(round, answers, own);
  int free = 0;
  for (std::size_t i = 0; i < round.size(); ++i) {
    const RoundQuery& q = round[i];
    const double expected = q.yes_no ? (reference.is_collision_free(q.q) ? 1.0 : 0.0)
                                     : reference.clearance_bound(q.q, q.cap, q.fcl_cap);
    EXPECT_EQ(answers[i], expected);
    free += expected > 0.0 ? 1 : 0;
  }
  return free;
}

/// The rounds, a checker for the thread that asks for them, its helper, and a reference checker.
struct RoundsFixture {
  explicit RoundsFixture(int count) : rounds(random_rounds(problem, count)) {}
  Problem problem = test::detour_problem();
  std::vector<std::vector<RoundQuery>> rounds;
  CollisionChecker reference{problem.scene};
  CollisionChecker own = reference.clone();
  QueryHelper helper{reference.clone()};
};

TEST(QueryHelper, ARoundOnTwoThreadsAnswersAndCountsAsOneThreadAlone) {
  RoundsFixture f(400);
  int free = 0, asked = 0;
  for (const std::vector<RoundQuery>& round : f.rounds) {
    free += expect_answers_as_alone(f.helper, round, f.own, f.reference);
    asked += static_cast<int>(round.size());
  }
  EXPECT_GT(free, 100);
  EXPECT_GT(asked - free, 100);
  // Every query counted once, in the checker of the thread that asked for the round.
  const CollisionCounters& a = f.own.counters();
  const CollisionCounters& b = f.reference.counters();
  EXPECT_EQ(a.state_checks, b.state_checks);
  EXPECT_EQ(a.clearance_queries, b.clearance_queries);
  EXPECT_EQ(a.box_tests, b.box_tests);
  EXPECT_EQ(a.triangle_tests, b.triangle_tests);
  EXPECT_EQ(query_work(a), query_work(b));
}

TEST(QueryHelper, TheHelpersCheckerCanBeReplacedBetweenRounds) {
  RoundsFixture f(40);
  for (const std::vector<RoundQuery>& round : f.rounds) {
    f.helper.set_checker(f.own.clone());
    expect_answers_as_alone(f.helper, round, f.own, f.reference);
  }
  EXPECT_GT(f.own.counters().clearance_queries, 100u);
}

}  // namespace
}  // namespace tandem
