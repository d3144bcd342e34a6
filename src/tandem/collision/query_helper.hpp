#pragma once
// A second core for one search's collision queries. The exact motion validation asks for the
// states of a motion in rounds of independent queries (the coarse states, then each level of the
// bisection: motion_validator.hpp); with a QueryHelper, the validator's thread and the helper's
// thread answer a round together, each query taken by whichever of the two is free first.
//
// Deterministic: a query's answer and its work (CollisionCounters) depend only on the query, not
// on the checker clone that answers it nor on what that clone answered before (clones answer
// alike; CollisionChecker.CountsTheWorkOfItsQueriesTheSameForTheSameQueries). So a round's
// answers, and the sums of the counters, are the same whichever thread took which query.
//
// Threading: run() is called from one thread at a time (the validator's). The helper thread reads
// the round and writes its answers only between run()'s start and its return; it waits for the
// next round spinning for a while, then asleep (std::atomic::wait). The validator's thread never
// waits for a helper that has not joined the round (not yet scheduled, or asleep): when it has
// taken the last query it closes the round, and waits only for a query the helper is answering.

#include <atomic>
#include <cstdint>
#include <exception>
#include <span>
#include <thread>

#include "tandem/collision/collision_checker.hpp"

namespace tandem {

/// One query of a round: a clearance bound (CollisionChecker::clearance_bound(q, cap, fcl_cap)),
/// or a yes/no collision query (is_collision_free(q), answered 1 when free and 0 when not).
struct RoundQuery {
  Config q;
  double cap = 0.0;
  double fcl_cap = 0.0;
  bool yes_no = false;
};

class QueryHelper {
 public:
  /// Starts the helper thread, which queries `checker` (a clone of the validator's).
  explicit QueryHelper(CollisionChecker checker);
  ~QueryHelper();
  QueryHelper(const QueryHelper&) = delete;
  QueryHelper& operator=(const QueryHelper&) = delete;

  /// Replaces the helper's checker (between rounds), e.g. after the validator's gained a grid.
  void set_checker(CollisionChecker checker);

  /// Answers every query of the round into `answers` (of the same size), with `own` on this
  /// thread and the helper's checker on the other; then adds the helper's counters to own's, so
  /// that `own` counts the whole round. Rethrows what a query threw on the helper's thread.
  void run(std::span<const RoundQuery> round, std::span<double> answers, CollisionChecker& own);

 private:
  /// The helper thread: waits for a round, takes part in it, says it is done.
  void serve();
  /// Waits until epoch_ differs from `seen` and returns it.
  std::uint32_t next_round(std::uint32_t seen) const;
  /// Closes the round if the helper has not joined it, else waits until the helper has left it
  /// and adds its counters to own's.
  void end_round(CollisionChecker& own);
  /// Takes the round's unanswered queries one by one until none is left.
  void take_queries(CollisionChecker& checker);

  CollisionChecker checker_;
  std::span<const RoundQuery> round_;
  std::span<double> answers_;
  /// The current round: posted (the helper may join it), joined by the helper, or closed (the
  /// validator's thread took every query alone, the helper may no longer join).
  enum class Round : std::uint8_t { posted, joined, closed };

  std::atomic<std::size_t> next_{0};     ///< the round's next query to take
  std::atomic<std::uint32_t> epoch_{0};  ///< one more for each round (and to stop)
  std::atomic<Round> round_state_{Round::closed};
  std::atomic<bool> helper_done_{true};  ///< the helper has left the round it joined
  std::atomic<bool> stop_{false};
  std::exception_ptr error_;  ///< thrown on the helper's thread in this round
  std::thread thread_;
};

}  // namespace tandem
