#include "tandem/collision/query_helper.hpp"

#include <utility>

namespace tandem {
namespace {

/// Rounds of spinning (each a pause of the core) before the helper sleeps until the next round:
/// a few hundred microseconds, longer than most of a search's gaps between two rounds (waking a
/// sleeping thread costs tens of microseconds, several clearance queries).
constexpr unsigned kSpins = 20000;

void pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

double answer_query(CollisionChecker& checker, const RoundQuery& query) {
  if (query.yes_no)
    return checker.is_collision_free(query.q) ? 1.0 : 0.0;
  return checker.clearance_bound(query.q, query.cap, query.fcl_cap);
}

}  // namespace

QueryHelper::QueryHelper(CollisionChecker checker)
    : checker_(std::move(checker)), thread_([this] { serve(); }) {}

QueryHelper::~QueryHelper() {
  stop_.store(true, std::memory_order_relaxed);
  epoch_.fetch_add(1, std::memory_order_release);
  epoch_.notify_one();
  thread_.join();
}

void QueryHelper::set_checker(CollisionChecker checker) {
  // Between rounds the helper touches nothing but epoch_.
  checker_ = std::move(checker);
}

void QueryHelper::run(std::span<const RoundQuery> round, std::span<double> answers,
                      CollisionChecker& own) {
  if (round.size() < 2) {
    // Nothing to share: no round.
    for (std::size_t i = 0; i < round.size(); ++i)
      answers[i] = answer_query(own, round[i]);
    return;
  }
  round_ = round;
  answers_ = answers;
  next_.store(0, std::memory_order_relaxed);
  helper_done_.store(false, std::memory_order_relaxed);
  round_state_.store(Round::posted, std::memory_order_release);
  epoch_.fetch_add(1, std::memory_order_release);
  epoch_.notify_one();
  std::exception_ptr own_error;
  try {
    take_queries(own);
  } catch (...) {
    // The helper may still be reading the round: it ends first.
    own_error = std::current_exception();
  }
  end_round(own);
  if (own_error)
    std::rethrow_exception(own_error);
  if (error_)
    std::rethrow_exception(std::exchange(error_, nullptr));
}

void QueryHelper::end_round(CollisionChecker& own) {
  // Closed before the helper joined: nothing of it to wait for. Joined: wait for the query it is
  // answering, yielding the core if that takes long (the helper may have been preempted).
  Round posted = Round::posted;
  if (round_state_.compare_exchange_strong(posted, Round::closed, std::memory_order_acq_rel))
    return;
  for (unsigned spins = 0; !helper_done_.load(std::memory_order_acquire); ++spins) {
    if (spins < kSpins)
      pause();
    else
      std::this_thread::yield();
  }
  own.add_counters(checker_.counters());
  checker_.reset_counters();
}

void QueryHelper::serve() {
  std::uint32_t seen = 0;
  for (;;) {
    seen = next_round(seen);
    if (stop_.load(std::memory_order_relaxed))
      return;
    Round posted = Round::posted;
    if (!round_state_.compare_exchange_strong(posted, Round::joined, std::memory_order_acq_rel))
      continue;  // closed without it
    try {
      take_queries(checker_);
    } catch (...) {
      error_ = std::current_exception();
      // The validator's thread finishes the round alone.
    }
    helper_done_.store(true, std::memory_order_release);
  }
}

std::uint32_t QueryHelper::next_round(std::uint32_t seen) const {
  for (unsigned i = 0; i < kSpins; ++i) {
    const std::uint32_t now = epoch_.load(std::memory_order_acquire);
    if (now != seen)
      return now;
    pause();
  }
  epoch_.wait(seen, std::memory_order_acquire);
  return epoch_.load(std::memory_order_acquire);
}

void QueryHelper::take_queries(CollisionChecker& checker) {
  for (;;) {
    const std::size_t i = next_.fetch_add(1, std::memory_order_relaxed);
    if (i >= round_.size())
      return;
    answers_[i] = answer_query(checker, round_[i]);
  }
}

}  // namespace tandem
