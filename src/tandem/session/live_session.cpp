#include "tandem/session/live_session.hpp"

#include <chrono>
#include <ctime>
#include <thread>

#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"

namespace tandem {
namespace {

std::shared_ptr<const OperatorSource> live_operator(const Problem& problem, const RunSpec& spec) {
  if (!is_interactive(spec.mode)) {
    throw InputError("--mode",
                     "a live session needs an interactive mode (interactive, "
                     "interactive-contact or irrt), not " +
                         std::string(to_string(spec.mode)));
  }
  return make_operator(problem, spec, OperatorClock::seconds);
}

JournalHeader header_for(const Problem& problem, const RunSpec& spec, const LiveOptions& options,
                         const OperatorSource& source) {
  JournalHeader h;
  h.problem = options.problem_name.empty() ? problem.source : options.problem_name;
  h.problem_digest = format_digest(problem_digest(problem));
  h.mode = std::string(to_string(spec.mode));
  h.settings = spec.settings;
  h.operator_description = source.describe();
  h.started = utc_now_iso8601();
  return h;
}

}  // namespace

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

LiveSession::LiveSession(const Problem& problem, const RunSpec& spec, const LiveOptions& options)
    : spec_(spec),
      options_(options),
      source_(live_operator(problem, spec)),
      checker_(problem.scene),
      validator_(problem.space, checker_),
      feed_(channel_) {
  spec_.settings = mode_settings(spec.mode, spec.settings);
  parameters_.set(spec_.settings.interaction);
  journal_.emplace(options.journal, header_for(problem, spec_, options, *source_));
  interaction_.feed = &feed_;
  interaction_.parameters = &parameters_;
  planner_ = make_planner(planner_name(spec.mode), validator_, problem.start, problem.goal,
                          spec_.settings, &interaction_);
}

LiveSession::~LiveSession() {
  if (operator_thread_)
    operator_thread_->stop();
}

void LiveSession::set_interaction(const InteractionSettings& settings) {
  const std::lock_guard lock(pending_mutex_);
  pending_ = settings;
  has_pending_.store(true, std::memory_order_release);
}

void LiveSession::journal_feed() {
  std::vector<FeedRecord> records = feed_.take_record();
  if (records.empty())
    return;
  for (const FeedRecord& r : records)
    journal_->operator_state(r.iteration, r.state);
  // What a watching operator sees: how far the tree is from where it holds the object now.
  roadmap_distance_.publish(planner_->distance_to_roadmap(records.back().state.device.q_device));
}

void LiveSession::journal_digest(const std::optional<std::string>& end_status) {
  JournalDigest d;
  d.steps = steps_;
  d.iterations = planner_->stats().iterations;
  d.nodes = planner_->stats().nodes;
  d.digest = format_digest(tree_digest(planner_->trees()));
  d.end_status = end_status;
  journal_->digest(d);
}

PlannerStatus LiveSession::run(const std::function<void(const LiveProgress&)>& progress) {
  operator_thread_ = std::make_unique<OperatorThread>(
      OperatorModel(checker_, source_), channel_, options_.operator_rate_hz, &roadmap_distance_);
  // The planner starts with the operator's first state in hand.
  while (channel_.latest() == nullptr && !stop_.load(std::memory_order_relaxed))
    std::this_thread::sleep_for(std::chrono::microseconds(100));

  const Stopwatch watch;
  double next_report = 1.0, next_digest = options_.digest_every_s;
  std::uint64_t iterations_at_report = 0;
  double last_report = 0.0;
  PlannerStatus status = PlannerStatus::running;
  while (status == PlannerStatus::running) {
    if (has_pending_.load(std::memory_order_acquire)) {
      const std::lock_guard lock(pending_mutex_);
      if (pending_) {
        parameters_.set(*pending_);
        journal_->params(steps_, *pending_);
        pending_.reset();
      }
      has_pending_.store(false, std::memory_order_relaxed);
    }
    status = planner_->step();
    ++steps_;
    journal_feed();
    if (status != PlannerStatus::running)
      break;
    if ((steps_ & 63) != 0)
      continue;
    const double t = watch.seconds();
    if (stop_.load(std::memory_order_relaxed)) {
      status = PlannerStatus::interrupted;
    } else if (t >= spec_.time_limit) {
      status = PlannerStatus::timeout;
    }
    if (t >= next_digest) {
      journal_digest(std::nullopt);
      next_digest = t + options_.digest_every_s;
    }
    if (progress && t >= next_report) {
      LiveProgress p;
      p.stats = planner_->stats();
      p.steps = steps_;
      p.elapsed_s = t;
      p.iterations_per_s =
          static_cast<double>(p.stats.iterations - iterations_at_report) / (t - last_report);
      p.operator_rate_hz = operator_thread_->achieved_rate();
      progress(p);
      iterations_at_report = p.stats.iterations;
      last_report = t;
      next_report = t + 1.0;
    }
  }
  operator_thread_->stop();
  journal_digest(std::string(to_string(status)));
  return status;
}

}  // namespace tandem
