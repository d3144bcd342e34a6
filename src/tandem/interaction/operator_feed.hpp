#pragma once
// How the planner thread gets the operator's state, without ever blocking.
//
// - VirtualTimeFeed: deterministic. Operator time is counted in planner iterations; the operator's
//   state changes every `period` iterations and is a pure function of that time, computed on the
//   planner thread when the planner first asks for it (its cost is reported as operator_seconds).
//   The same seed and source give the same tree.
// - LiveFeed: the latest state an OperatorThread published (wall-clock). It records, for each
// iteration
//   at which the planner saw a new state, that state: with the planner's seed, this record replays
//   the run exactly.
//
// Threading: at() is called by the planner thread only.

#include <cstdint>
#include <memory>
#include <vector>

#include "tandem/core/stopwatch.hpp"
#include "tandem/interaction/latest_value.hpp"
#include "tandem/interaction/operator_model.hpp"

namespace tandem {

class OperatorFeed {
 public:
  virtual ~OperatorFeed() = default;
  /// The operator's state for this planner iteration, or nullptr if there is none yet.
  virtual const OperatorState* at(std::uint64_t iteration) = 0;
  /// Seconds the planner thread spent computing operator states.
  double operator_seconds() const { return operator_seconds_; }

 protected:
  double operator_seconds_ = 0.0;
};

class VirtualTimeFeed final : public OperatorFeed {
 public:
  VirtualTimeFeed(OperatorModel model, std::uint64_t period = 10);
  const OperatorState* at(std::uint64_t iteration) override;

 private:
  OperatorModel model_;
  std::uint64_t period_;
  OperatorState current_;
  bool have_ = false;
};

/// What the planner saw of a live operator: the state it used from each iteration on.
struct FeedRecord {
  std::uint64_t iteration;
  OperatorState state;
};

class LiveFeed final : public OperatorFeed {
 public:
  explicit LiveFeed(LatestValue<OperatorState>& channel) : channel_(channel) {}
  const OperatorState* at(std::uint64_t iteration) override;
  const std::vector<FeedRecord>& record() const { return record_; }

 private:
  LatestValue<OperatorState>& channel_;
  std::uint64_t last_sequence_ = 0;
  std::vector<FeedRecord> record_;
};

/// Replays a LiveFeed's record: from each recorded iteration on, the recorded state.
class ReplayFeed final : public OperatorFeed {
 public:
  explicit ReplayFeed(std::vector<FeedRecord> record) : record_(std::move(record)) {}
  const OperatorState* at(std::uint64_t iteration) override;

 private:
  std::vector<FeedRecord> record_;
  std::size_t next_ = 0;
  const OperatorState* current_ = nullptr;
};

}  // namespace tandem
