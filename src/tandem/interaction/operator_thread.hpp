#pragma once
// The operator thread of the papers: it runs an OperatorModel at a fixed wall-clock rate and
// publishes each state into a LatestValue channel for the planner. (The I-RRT's guidance force
// goes back through the live session, not through this thread.)
//
// Threading: the constructor starts the thread; stop() (or the destructor) ends and joins it. The
// model is used only by the thread. published() and achieved_rate() may be read from any thread.

#include <atomic>
#include <cstdint>
#include <thread>

#include "tandem/interaction/latest_value.hpp"
#include "tandem/interaction/operator_model.hpp"
#include "tandem/interaction/pacer.hpp"

namespace tandem {

class OperatorThread {
 public:
  /// Publishes compute(t) with t = seconds since start, `rate_hz` times a second (at most). With
  /// `roadmap`, a simulated operator that watches the roadmap keeps pace with it (see Pacer): the
  /// planner thread publishes there the distance from the latest q_device it saw to the roadmap.
  OperatorThread(OperatorModel model, LatestValue<OperatorState>& channel, double rate_hz,
                 LatestValue<double>* roadmap = nullptr);
  ~OperatorThread();
  OperatorThread(const OperatorThread&) = delete;
  OperatorThread& operator=(const OperatorThread&) = delete;

  void stop();
  /// Blocks the caller until the first state is in the channel (the planner starts with it in
  /// hand), or until `cancel` (may be null) is set.
  void wait_for_first_state(const std::atomic<bool>* cancel = nullptr) const;
  std::uint64_t published() const { return published_.load(std::memory_order_relaxed); }
  /// States per second actually published (the loop's rate, nearest-obstacle query included).
  double achieved_rate() const;
  /// A simulated operator that watches the roadmap: the states at which it found the roadmap
  /// beyond its lead, and the seconds it spent going back to it (Pacer).
  std::uint64_t waits() const { return waits_.load(std::memory_order_relaxed); }
  double waited_s() const { return waited_s_.load(std::memory_order_relaxed); }

 private:
  void run();

  OperatorModel model_;
  LatestValue<OperatorState>& channel_;
  LatestValue<double>* roadmap_;
  double period_s_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> published_{0};
  std::atomic<double> elapsed_s_{0.0};
  std::atomic<std::uint64_t> waits_{0};
  std::atomic<double> waited_s_{0.0};
  std::thread thread_;
};

}  // namespace tandem
