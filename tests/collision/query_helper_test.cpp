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

TEST(QueryHelper, ARoundOnTwoThreadsAnswersAndCountsAsOneThreadAlone) {
  const Problem p = test::detour_problem();
  const std::vector<std::vector<RoundQuery>> rounds = random_rounds(p, 400);
  CollisionChecker reference(p.scene);
  CollisionChecker own = reference.clone();
  QueryHelper helper(reference.clone());
  int free = 0, colliding = 0;
  for (const std::vector<RoundQuery>& round : rounds) {
    std::vector<double> answers(round.size(), -1.0);
    helper.run(round, answers, own);
    for (std::size_t i = 0; i < round.size(); ++i) {
      const RoundQuery& q = round[i];
      const double expected = q.yes_no ? (reference.is_collision_free(q.q) ? 1.0 : 0.0)
                                       : reference.clearance_bound(q.q, q.cap, q.fcl_cap);
      EXPECT_EQ(answers[i], expected);
      (expected > 0.0 ? free : colliding) += 1;
    }
  }
  EXPECT_GT(free, 100);
  EXPECT_GT(colliding, 100);
  // Every query counted once, in the checker of the thread that asked for the round.
  const CollisionCounters& a = own.counters();
  const CollisionCounters& b = reference.counters();
  EXPECT_EQ(a.state_checks, b.state_checks);
  EXPECT_EQ(a.clearance_queries, b.clearance_queries);
  EXPECT_EQ(a.box_tests, b.box_tests);
  EXPECT_EQ(a.triangle_tests, b.triangle_tests);
  EXPECT_EQ(query_work(a), query_work(b));
}

TEST(QueryHelper, TheHelpersCheckerCanBeReplacedBetweenRounds) {
  const Problem p = test::detour_problem();
  const std::vector<std::vector<RoundQuery>> rounds = random_rounds(p, 40);
  CollisionChecker own(p.scene);
  CollisionChecker reference = own.clone();
  QueryHelper helper(own.clone());
  for (const std::vector<RoundQuery>& round : rounds) {
    helper.set_checker(own.clone());
    std::vector<double> answers(round.size());
    helper.run(round, answers, own);
    for (std::size_t i = 0; i < round.size(); ++i) {
      if (!round[i].yes_no) {
        EXPECT_EQ(answers[i],
                  reference.clearance_bound(round[i].q, round[i].cap, round[i].fcl_cap));
      }
    }
  }
  EXPECT_GT(own.counters().clearance_queries, 100u);
}

}  // namespace
}  // namespace tandem
