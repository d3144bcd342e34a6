#pragma once
// A live interactive session: the papers' two loops on two threads, journaled as it runs.
//
// The operator thread (OperatorThread) reads the live operator (an OperatorSwitch: a simulated
// operator or recorded trace, the browser, a SpaceMouse), finds the nearest obstacle and publishes
// the state; the planner thread (the one that calls run()) steps the interactive planner, which
// takes the latest state without ever waiting. Everything the planner saw is written to the
// session's journal as it happens (see journal.hpp), so `tandem replay` rebuilds the same tree, and
// a killed session loses nothing it had journaled.
//
// The session is driven from any thread (the viewer's): new interaction settings, pause, resume,
// step, reset (start the planner over), stop. An observer (the viewer's bridge) is called on the
// planner thread a few tens of times a second, when it may read the planner.
//
// Threading: construct, run() and planner() on one thread (the planner thread); the commands,
// operator_input() and progress() from any thread.

#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "tandem/interaction/interaction.hpp"
#include "tandem/interaction/operator_thread.hpp"
#include "tandem/operators/operator_switch.hpp"
#include "tandem/runs/run.hpp"
#include "tandem/scene/take_out.hpp"
#include "tandem/session/journal.hpp"

namespace tandem {

struct LiveOptions {
  std::string problem_name;       ///< as the user named it (written in the journal)
  TakeOutOptions take_out;        ///< and, for a STEP or IGES problem, its --part and options
  std::filesystem::path journal;  ///< where the session is journaled
  double operator_rate_hz = 1000.0;
  double digest_every_s = 2.0;  ///< a tree digest in the journal this often
  /// After the planner ends (solved, time limit), stay until stop(): the viewer keeps showing the
  /// result and may reset. Otherwise run() returns then.
  bool stay = false;
  bool start_paused = false;
  /// Try to connect to spacenavd for a SpaceMouse.
  bool spacemouse = true;
  /// How often the observer is called.
  double observe_every_s = 1.0 / 30.0;
  /// An operator the caller provides (the Python module's), on the wall clock, instead of the
  /// spec's simulated one; read on the operator thread.
  std::shared_ptr<const OperatorSource> operator_source;
};

struct LiveProgress {
  PlannerStats stats;
  PlannerStatus status = PlannerStatus::running;  ///< the session's: timeout once the limit passed
  std::uint64_t steps = 0;
  std::uint64_t resets = 0;
  bool paused = false;
  double elapsed_s = 0.0;         ///< planning time since the start or the last reset, pauses out
  double iterations_per_s = 0.0;  ///< over the last second or so
  double operator_rate_hz = 0.0;  ///< states the operator thread published per second
  /// The last measured time from a browser input event reaching the session to the first operator
  /// node grown from it (seconds), and that event's id; 0 if none yet.
  double input_latency_s = 0.0;
  std::uint64_t input_latency_id = 0;
};

class LiveSession;

/// Called on the planner thread; may read the planner (and copy what it needs) but not keep it.
class LiveObserver {
 public:
  virtual ~LiveObserver() = default;
  /// About every observe_every_s, after each step while paused-stepping, and when the planner ends.
  virtual void observe(const LiveSession& session, const Planner& planner) = 0;
  /// The planner was started over: the trees are empty again (observe() follows).
  virtual void restarted() = 0;
};

class LiveSession {
 public:
  /// Throws InputError for a spec the problem cannot run live (not an interactive mode, no guide,
  /// a trace in ticks) or a journal that cannot be written. The operator "browser" means no
  /// simulated operator: the part waits at the start for a person.
  LiveSession(const Problem& problem, const RunSpec& spec, const LiveOptions& options);
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  /// Runs the planner on the calling thread until it solves or spec.time_limit of planning passes
  /// (then, with options.stay, waits for a reset or stop()), or until stop(); calls `progress`
  /// about once a second. Returns the session's status at the end.
  using ProgressCallback = std::function<void(const LiveProgress&)>;
  PlannerStatus run(const ProgressCallback& progress = {});
  void set_observer(LiveObserver* observer) { observer_ = observer; }

  // Commands, thread-safe; they take effect after the planner's current step, in order.
  void stop() { stop_.store(true, std::memory_order_relaxed); }
  /// Whether stop() was called (from any thread).
  bool stopping() const { return stop_.load(std::memory_order_relaxed); }
  /// New interaction settings, applied (and journaled) after the planner's current step.
  void set_interaction(const InteractionSettings& settings);
  void pause();
  void resume();
  /// While paused: one more planner step (ignored while the planner runs).
  void step_once();
  /// Starts the planner over (same seed, new trees); the journal records where.
  void reset();

  /// The live operator (switch inputs, browser poses). Thread-safe.
  OperatorSwitch& operator_input() { return *switch_; }
  const OperatorSwitch& operator_input() const { return *switch_; }
  /// The interaction settings in force (or about to be). Thread-safe.
  InteractionSettings interaction() const;
  /// The latest progress (updated on the observer's schedule). Thread-safe.
  LiveProgress progress() const;

  // Planner thread only (the observer's callbacks run there).
  const Planner& planner() const { return *planner_; }
  std::uint64_t steps() const { return steps_; }
  /// The operator's state, if any: the one the planner used last while it steps; while it does
  /// not (paused, solved, out of time), the operator thread's latest, so that a viewer shows the
  /// operator where the person put it.
  const OperatorState* operator_state() const { return have_state_ ? &last_state_ : nullptr; }
  /// The I-RRT's latest guidance force, if the planner publishes one.
  const Guidance* guidance() const { return have_guidance_ ? &last_guidance_ : nullptr; }
  const RunSpec& spec() const { return spec_; }

  const std::filesystem::path& journal_file() const { return journal_->file(); }

 private:
  struct Loop;
  void start_operator();
  /// One planner step; false when the session ends with the planner.
  bool step_planner(Loop& loop);
  /// Planning time, time limit, digests, guidance; false when the session ends on the limit.
  bool keep_time(Loop& loop, double t);
  LiveProgress measure_progress(Loop& loop, double t);
  void publish_progress(Loop& loop, double t, const ProgressCallback& progress);
  void apply_commands();
  void start_planner();
  void journal_feed();
  void show_idle_operator();
  void journal_digest(const std::optional<std::string>& end_status);
  void measure_latency();

  const Problem& problem_;
  RunSpec spec_;
  LiveOptions options_;
  std::shared_ptr<OperatorSwitch> switch_;
  CollisionChecker checker_;
  MotionValidator validator_;
  LatestValue<OperatorState> channel_;
  LatestValue<double> roadmap_distance_;
  LatestValue<Guidance> guidance_channel_;
  LiveFeed feed_;
  InteractionParameters parameters_;
  Interaction interaction_;
  std::unique_ptr<Planner> planner_;
  std::optional<JournalWriter> journal_;  ///< opened once the settings are known
  std::unique_ptr<OperatorThread> operator_thread_;
  LiveObserver* observer_ = nullptr;
  std::atomic<bool> stop_{false};

  // Planner thread.
  std::uint64_t steps_ = 0;
  std::uint64_t resets_ = 0;
  PlannerStatus status_ = PlannerStatus::running;
  bool paused_ = false;
  std::uint64_t steps_requested_ = 0;
  OperatorState last_state_;
  bool have_state_ = false;
  Guidance last_guidance_;
  bool have_guidance_ = false;
  OperatorInput input_ = OperatorInput::simulated;  ///< as last journaled
  std::uint64_t latency_id_ = 0;
  double latency_s_ = 0.0;

  // Commands from other threads.
  struct Pending {
    std::optional<InteractionSettings> settings;
    std::optional<bool> paused;
    std::uint64_t steps = 0;
    bool reset = false;
  };
  mutable std::mutex pending_mutex_;
  Pending pending_;
  InteractionSettings settings_now_;  ///< guarded by pending_mutex_
  std::atomic<bool> has_pending_{false};
  LiveProgress progress_;  ///< guarded by pending_mutex_
};

/// Throws InputError (naming --mode) unless the spec's planner takes an operator: the one check
/// for every way a live session is started.
void require_live_planner(const RunSpec& spec);

}  // namespace tandem
