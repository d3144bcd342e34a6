#include "tandem/session/virtual_session.hpp"

#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/runs/run.hpp"
#include "tandem/session/live_session.hpp"

namespace tandem {

/// A VirtualTimeFeed that remembers each new state with the iteration that first used it (what a
/// LiveFeed records, and the journal keeps).
class VirtualSession::RecordingFeed final : public OperatorFeed {
 public:
  RecordingFeed(OperatorModel model, std::uint64_t period) : inner_(std::move(model), period) {}

  const OperatorState* at(std::uint64_t iteration, const RoadmapView* roadmap) override {
    const OperatorState* s = inner_.at(iteration, roadmap);
    if (s != nullptr && s->sequence != last_sequence_) {
      last_sequence_ = s->sequence;
      record_.push_back({iteration, *s});
    }
    operator_seconds_ = inner_.operator_seconds();
    return s;
  }
  std::vector<FeedRecord> take_record() { return std::exchange(record_, {}); }

 private:
  VirtualTimeFeed inner_;
  std::uint64_t last_sequence_ = 0;
  std::vector<FeedRecord> record_;
};

VirtualSession::VirtualSession(const Problem& problem, const RunSpec& spec,
                               std::shared_ptr<const OperatorSource> source,
                               const VirtualSessionOptions& options)
    : problem_(problem),
      spec_(spec),
      options_(options),
      checker_(problem.scene),
      validator_(problem.space, checker_),
      parameters_(spec.settings.interaction) {
  interaction_.parameters = &parameters_;
  std::string operator_text = "none";
  if (source != nullptr && !uses_operator(spec_))
    throw InputError("operator", spec_.mode + " plans alone: it takes no operator");
  if (uses_operator(spec_)) {
    if (source == nullptr)
      source = make_operator(problem, spec_, OperatorClock::ticks);
    operator_text = source->describe();
    feed_ = std::make_unique<RecordingFeed>(OperatorModel(checker_, std::move(source)),
                                            spec_.operator_period);
    interaction_.feed = feed_.get();
  }
  if (!options_.journal.empty() && feed_ == nullptr) {
    throw InputError("journal",
                     "only the sessions of planners that take an operator are "
                     "journaled; " +
                         spec_.mode + " plans alone (its seed repeats it)");
  }
  if (!options_.journal.empty())
    journal_.emplace(options_.journal, session_header(problem, options_.problem_name,
                                                      options_.take_out, spec_, operator_text));
  // One thread: the planner and the operator share it (spec.settings.threads is not used).
  planner_ = make_planner(spec_.mode, validator_, problem.start, problem.goal, spec_.settings,
                          feed_ != nullptr ? &interaction_ : nullptr);
  next_digest_ = options_.digest_every;
}

VirtualSession::~VirtualSession() {
  try {
    finish();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw; the journal
  }                // keeps what it had written.
}

const std::filesystem::path* VirtualSession::journal_file() const {
  return journal_ ? &journal_->file() : nullptr;
}

PlannerStatus VirtualSession::step(std::uint64_t steps) {
  for (std::uint64_t k = 0; k < steps && status_ == PlannerStatus::running && !finished_; ++k) {
    status_ = planner_->step();
    ++steps_;
    journal_feed();
    if (journal_ && steps_ >= next_digest_) {
      journal_digest(std::nullopt);
      next_digest_ = steps_ + options_.digest_every;
    }
  }
  return status_;
}

PlannerStatus VirtualSession::run() {
  const Stopwatch watch;
  while (status_ == PlannerStatus::running && !finished_) {
    if (planner_->stats().iterations >= spec_.max_iterations) {
      status_ = PlannerStatus::iteration_limit;
    } else if (steps_ % 64 == 0 && watch.seconds() >= spec_.time_limit) {
      status_ = PlannerStatus::timeout;
    } else {
      step(1);
    }
  }
  return status_;
}

void VirtualSession::set_interaction(const InteractionSettings& settings) {
  parameters_.set(settings);
  if (journal_)
    journal_->params(steps_, settings);
}

void VirtualSession::finish() {
  if (finished_)
    return;
  finished_ = true;
  if (journal_)
    journal_digest(std::string(to_string(status_)));
}

void VirtualSession::journal_feed() {
  if (feed_ == nullptr)
    return;
  std::vector<FeedRecord> records = feed_->take_record();
  if (records.empty())
    return;
  if (journal_) {
    for (const FeedRecord& r : records)
      journal_->operator_state(r.iteration, r.state);
  }
  last_state_ = records.back().state;
  have_state_ = true;
}

void VirtualSession::journal_digest(const std::optional<std::string>& end_status) {
  journal_->digest(trees_digest(*planner_, steps_, end_status));
}

}  // namespace tandem
