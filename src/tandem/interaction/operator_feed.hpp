#pragma once
// How the planner thread gets the operator's state, without ever blocking.
//
// - VirtualTimeFeed: deterministic. Operator time is counted in planner iterations; the operator's
//   state changes every `period` iterations and is a function of that time and of what the
//   operator saw of the roadmap (its pace, see Pacer), computed on the planner thread when the
//   planner first asks for it (its cost is reported as operator_seconds). The same seed and source
//   give the same tree.
// - LiveFeed: the latest state an OperatorThread published (wall-clock). It records, for each
//   iteration at which the planner saw a new state, that state: with the planner's seed, this
//   record replays the run exactly.
//
// Threading: at() and peek() are called by the planner thread only.

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "tandem/core/stopwatch.hpp"
#include "tandem/interaction/latest_value.hpp"
#include "tandem/interaction/operator_model.hpp"
#include "tandem/interaction/pacer.hpp"

namespace tandem {

/// What an operator sees of the roadmap (the planner's trees, as a viewer shows them).
class RoadmapView {
 public:
  virtual ~RoadmapView() = default;
  /// Metric distance from q to the nearest node of the tree the operator carries along (the one
  /// rooted at the start; near the goal, the goal's tree is always close and says nothing).
  virtual double distance_to_roadmap(const Config& q) const = 0;
};

class OperatorFeed {
 public:
  virtual ~OperatorFeed() = default;
  /// The operator's state for this planner iteration, or nullptr if there is none yet. `roadmap`,
  /// when given, is what a simulated operator that watches the roadmap looks at.
  virtual const OperatorState* at(std::uint64_t iteration,
                                  const RoadmapView* roadmap = nullptr) = 0;
  /// Seconds the planner thread spent computing operator states.
  double operator_seconds() const { return operator_seconds_; }

 protected:
  double operator_seconds_ = 0.0;
};

class VirtualTimeFeed final : public OperatorFeed {
 public:
  VirtualTimeFeed(OperatorModel model, std::uint64_t period = 10);
  const OperatorState* at(std::uint64_t iteration, const RoadmapView* roadmap = nullptr) override;
  /// Updates at which the operator found the roadmap beyond its lead and went back.
  unsigned long long operator_waits() const { return pacer_.waits(); }

 private:
  OperatorModel model_;
  std::uint64_t period_;
  Pacer pacer_;
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
  /// With `roadmap_distance`, each new state the planner takes publishes there how far the tree
  /// is from its q_device (what a watching operator sees, see Pacer). Without `keep_record`,
  /// nothing is recorded (a run that is not journaled).
  explicit LiveFeed(LatestValue<OperatorState>& channel,
                    LatestValue<double>* roadmap_distance = nullptr, bool keep_record = true)
      : channel_(channel), roadmap_distance_(roadmap_distance), keep_record_(keep_record) {}
  const OperatorState* at(std::uint64_t iteration, const RoadmapView* roadmap = nullptr) override;
  /// The latest state published, without the planner taking it (nothing recorded): what to show
  /// of the operator while the planner does not step (paused, solved, out of time). The planner's
  /// next at() still takes and records it.
  const OperatorState* peek() { return channel_.latest(); }
  const std::vector<FeedRecord>& record() const { return record_; }
  /// Hands over the record so far and starts a new one (a journal writes it away as it grows).
  std::vector<FeedRecord> take_record() { return std::exchange(record_, {}); }
  /// For a new planner (the user started over): its first state is recorded, even if it is the
  /// one the previous planner saw last (a replay starts the new planner with no state in hand).
  void restart() { last_sequence_ = 0; }

 private:
  LatestValue<OperatorState>& channel_;
  LatestValue<double>* roadmap_distance_;
  bool keep_record_;
  std::uint64_t last_sequence_ = 0;
  std::vector<FeedRecord> record_;
};

/// Replays a LiveFeed's record: from each recorded iteration on, the recorded state.
class ReplayFeed final : public OperatorFeed {
 public:
  explicit ReplayFeed(std::vector<FeedRecord> record) : record_(std::move(record)) {}
  const OperatorState* at(std::uint64_t iteration, const RoadmapView* roadmap = nullptr) override;
  /// The state the planner was given last, if any.
  const OperatorState* current() const { return current_; }

 private:
  std::vector<FeedRecord> record_;
  std::size_t next_ = 0;
  const OperatorState* current_ = nullptr;
};

}  // namespace tandem
