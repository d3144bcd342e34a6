#pragma once
// A session in virtual time: the planner stepped on the caller's thread, iteration by iteration,
// with an operator that is any OperatorSource on the ticks clock (a simulated operator, a trace,
// or one the caller provides: the Python module's operators are callables) — journaled as a live
// session is, so `tandem replay` rebuilds the same trees from the journal.
//
// Operator time is counted in planner iterations, as in the runs of an experiment
// (VirtualTimeFeed): the operator's state changes every spec.operator_period iterations. What the
// planner was given, and from which iteration, is what the journal records; an operator that is
// not a pure function of time (a person, a learned policy) is replayed from that record.
//
// Threading: one thread (the caller's) for everything; the operator source is called on it.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/interaction/interaction.hpp"
#include "tandem/interaction/operator_feed.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/runs/run_spec.hpp"
#include "tandem/scene/problem.hpp"
#include "tandem/session/journal.hpp"

namespace tandem {

struct VirtualSessionOptions {
  std::string problem_name;            ///< as the user named it (written in the journal)
  TakeOutOptions take_out;             ///< and, for a STEP or IGES problem, its part and options
  std::filesystem::path journal;       ///< "" for none
  std::uint64_t digest_every = 10000;  ///< a tree digest in the journal every this many steps
};

class VirtualSession {
 public:
  /// `source` drives the operator of an interactive planner (null: the spec's operator, made as
  /// an experiment makes it; a planner without an operator takes none). Throws InputError for a
  /// spec the problem cannot run, a journal that cannot be written, or a journal or a source for
  /// a planner that plans alone (its seed repeats it; the replay is of operators).
  VirtualSession(const Problem& problem, const RunSpec& spec,
                 std::shared_ptr<const OperatorSource> source,
                 const VirtualSessionOptions& options);
  ~VirtualSession();
  VirtualSession(const VirtualSession&) = delete;
  VirtualSession& operator=(const VirtualSession&) = delete;

  /// Up to `steps` planner steps, fewer if the planner ends; returns its status.
  PlannerStatus step(std::uint64_t steps = 1);
  /// Steps until the planner ends, spec.time_limit of stepping passes or spec.max_iterations;
  /// returns the status (timeout, iteration_limit when a limit ended it).
  PlannerStatus run();
  /// New interaction settings (alpha, contact distance and samples, ...), from the next step on;
  /// journaled.
  void set_interaction(const InteractionSettings& settings);
  /// Writes the journal's end record (once; the destructor does it if not done).
  void finish();

  const Planner& planner() const { return *planner_; }
  PlannerStatus status() const { return status_; }
  std::uint64_t steps() const { return steps_; }
  /// The operator state the planner was given last, if any.
  const OperatorState* operator_state() const { return have_state_ ? &last_state_ : nullptr; }
  const std::filesystem::path* journal_file() const;

 private:
  class RecordingFeed;
  void journal_feed();
  void journal_digest(const std::optional<std::string>& end_status);

  const Problem& problem_;
  RunSpec spec_;
  VirtualSessionOptions options_;
  CollisionChecker checker_;
  MotionValidator validator_;
  std::unique_ptr<RecordingFeed> feed_;
  InteractionParameters parameters_;
  Interaction interaction_;
  std::unique_ptr<Planner> planner_;
  std::optional<JournalWriter> journal_;
  PlannerStatus status_ = PlannerStatus::running;
  std::uint64_t steps_ = 0;
  std::uint64_t next_digest_ = 0;
  bool finished_ = false;
  OperatorState last_state_;
  bool have_state_ = false;
};

}  // namespace tandem
