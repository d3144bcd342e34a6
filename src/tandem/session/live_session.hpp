#pragma once
// A live interactive session: the papers' two loops on two threads, journaled as it runs.
//
// The operator thread (OperatorThread) reads the operator's source on the wall clock — a simulated
// operator, a recorded trace in seconds, later a device — finds the nearest obstacle and publishes
// the state; the planner thread (the one that calls run()) steps the interactive planner, which
// takes the latest state without ever waiting. Everything the planner saw is written to the
// session's journal as it happens (see journal.hpp), so `tandem replay` rebuilds the same tree, and
// a killed session loses nothing it had journaled.
//
// Threading: construct, run() and the accessors on one thread (the planner thread); stop() and
// set_interaction() from any thread.

#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "tandem/experiments/run.hpp"
#include "tandem/interaction/operator_thread.hpp"
#include "tandem/session/journal.hpp"

namespace tandem {

struct LiveOptions {
  std::string problem_name;       ///< as the user named it (written in the journal)
  std::filesystem::path journal;  ///< where the session is journaled
  double operator_rate_hz = 1000.0;
  double digest_every_s = 2.0;  ///< a tree digest in the journal this often
};

struct LiveProgress {
  PlannerStats stats;
  std::uint64_t steps = 0;
  double elapsed_s = 0.0;
  double iterations_per_s = 0.0;  ///< since the previous report
  double operator_rate_hz = 0.0;  ///< states the operator thread published per second
};

class LiveSession {
 public:
  /// Throws InputError for a spec the problem cannot run live (not an interactive mode, no guide,
  /// a trace in ticks) or a journal that cannot be written.
  LiveSession(const Problem& problem, const RunSpec& spec, const LiveOptions& options);
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  /// Runs the planner on the calling thread until it solves, spec.time_limit passes, or stop() is
  /// called; calls `progress` about once a second. Returns the planner's status (timeout or
  /// interrupted when it did not solve).
  PlannerStatus run(const std::function<void(const LiveProgress&)>& progress = {});

  /// Ends run() at its next step. Thread-safe.
  void stop() { stop_.store(true, std::memory_order_relaxed); }
  /// New interaction settings, applied (and journaled) after the planner's current step.
  void set_interaction(const InteractionSettings& settings);

  const Planner& planner() const { return *planner_; }
  std::uint64_t steps() const { return steps_; }
  const std::filesystem::path& journal_file() const { return journal_->file(); }

 private:
  void journal_feed();
  void journal_digest(const std::optional<std::string>& end_status);

  RunSpec spec_;
  LiveOptions options_;
  std::shared_ptr<const OperatorSource> source_;
  CollisionChecker checker_;
  MotionValidator validator_;
  LatestValue<OperatorState> channel_;
  LatestValue<double> roadmap_distance_;
  LiveFeed feed_;
  InteractionParameters parameters_;
  Interaction interaction_;
  std::unique_ptr<Planner> planner_;
  std::optional<JournalWriter> journal_;  ///< opened once the settings are known
  std::unique_ptr<OperatorThread> operator_thread_;
  std::atomic<bool> stop_{false};
  std::uint64_t steps_ = 0;
  std::mutex pending_mutex_;
  std::optional<InteractionSettings> pending_;
  std::atomic<bool> has_pending_{false};
};

/// The current UTC time, ISO 8601 (for journal headers).
std::string utc_now_iso8601();

}  // namespace tandem
