#include "tandem/session/live_session.hpp"

#include <chrono>
#include <thread>

#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

std::shared_ptr<OperatorSwitch> live_operator(const Problem& problem, const RunSpec& spec,
                                              const LiveOptions& options) {
  require_live_planner(spec);
  std::shared_ptr<const OperatorSource> simulated = options.operator_source;
  if (simulated == nullptr && spec.operator_name != "browser")
    simulated = make_operator(problem, spec, OperatorClock::seconds);
  const bool spacemouse = options.spacemouse;
  std::unique_ptr<SpaceNav> nav;
  std::string why = "no SpaceMouse (not asked for)";
  if (spacemouse)
    nav = SpaceNav::open(&why);
  return std::make_shared<OperatorSwitch>(problem.space, std::move(simulated), problem.start,
                                          std::move(nav), std::move(why));
}

}  // namespace

void require_live_planner(const RunSpec& spec) {
  if (!uses_operator(spec)) {
    throw InputError("--mode",
                     "a live session needs a planner that takes an operator, not " + spec.mode);
  }
}

LiveSession::LiveSession(const Problem& problem, const RunSpec& spec, const LiveOptions& options)
    : problem_(problem),
      spec_(spec),
      options_(options),
      switch_(live_operator(problem, spec, options)),
      checker_(problem.scene),
      validator_(problem.space, checker_),
      feed_(channel_, &roadmap_distance_) {
  parameters_.set(spec_.settings.interaction);
  settings_now_ = spec_.settings.interaction;
  paused_ = options.start_paused;
  input_ = switch_->snapshot().input;
  journal_.emplace(options.journal, session_header(problem, options.problem_name, options.take_out,
                                                   spec_, switch_->describe()));
  journal_->event(0, "input " + std::string(to_string(input_)));
  interaction_.feed = &feed_;
  interaction_.parameters = &parameters_;
  interaction_.guidance = &guidance_channel_;
  start_planner();
}

LiveSession::~LiveSession() {
  if (operator_thread_)
    operator_thread_->stop();
}

void LiveSession::start_planner() {
  planner_.reset();
  feed_.restart();
  planner_ = make_planner(spec_.mode, validator_, problem_.start, problem_.goal, spec_.settings,
                          &interaction_);
  status_ = PlannerStatus::running;
  have_guidance_ = false;
}

void LiveSession::set_interaction(const InteractionSettings& settings) {
  const std::lock_guard lock(pending_mutex_);
  pending_.settings = settings;
  settings_now_ = settings;
  has_pending_.store(true, std::memory_order_release);
}

void LiveSession::pause() {
  const std::lock_guard lock(pending_mutex_);
  pending_.paused = true;
  has_pending_.store(true, std::memory_order_release);
}

void LiveSession::resume() {
  const std::lock_guard lock(pending_mutex_);
  pending_.paused = false;
  has_pending_.store(true, std::memory_order_release);
}

void LiveSession::step_once() {
  const std::lock_guard lock(pending_mutex_);
  ++pending_.steps;
  has_pending_.store(true, std::memory_order_release);
}

void LiveSession::reset() {
  const std::lock_guard lock(pending_mutex_);
  pending_.reset = true;
  has_pending_.store(true, std::memory_order_release);
}

InteractionSettings LiveSession::interaction() const {
  const std::lock_guard lock(pending_mutex_);
  return settings_now_;
}

LiveProgress LiveSession::progress() const {
  const std::lock_guard lock(pending_mutex_);
  return progress_;
}

void LiveSession::apply_commands() {
  if (!has_pending_.load(std::memory_order_acquire))
    return;
  Pending p;
  {
    const std::lock_guard lock(pending_mutex_);
    p = std::exchange(pending_, {});
    has_pending_.store(false, std::memory_order_relaxed);
  }
  if (p.reset) {
    journal_->reset(steps_);
    ++resets_;
    start_planner();
    if (observer_ != nullptr)
      observer_->restarted();
  }
  if (p.settings) {
    parameters_.set(*p.settings);
    journal_->params(steps_, *p.settings);
  }
  if (p.paused && *p.paused != paused_) {
    paused_ = *p.paused;
    journal_->event(steps_, paused_ ? "pause" : "resume");
  }
  // A step is one iteration of a paused planner; asked for while it runs, it means nothing (and
  // must not fire later, at the next pause).
  if (p.steps > 0 && paused_) {
    journal_->event(steps_, "step " + std::to_string(p.steps));
    steps_requested_ += p.steps;
  }
}

void LiveSession::journal_feed() {
  std::vector<FeedRecord> records = feed_.take_record();
  if (records.empty())
    return;
  for (const FeedRecord& r : records)
    journal_->operator_state(r.iteration, r.state);
  last_state_ = records.back().state;
  have_state_ = true;
}

void LiveSession::show_idle_operator() {
  // Not journaled: the planner takes (and the journal records) this state at its next step.
  if (const OperatorState* s = feed_.peek()) {
    last_state_ = *s;
    have_state_ = true;
  }
}

void LiveSession::measure_latency() {
  // The first operator node grown after a browser event reached the session: its latency.
  // Called after a step that added operator nodes (see run()).
  const std::uint64_t id = last_state_.device.input_id;
  if (!have_state_ || id == 0 || id == latency_id_)
    return;
  const auto received = switch_->input_time(id);
  if (!received)
    return;
  latency_id_ = id;
  latency_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - *received).count();
}

void LiveSession::journal_digest(const std::optional<std::string>& end_status) {
  journal_->digest(trees_digest(*planner_, steps_, end_status));
}

// run() in phases: the operator starts, then each turn of the loop applies the commands, steps
// the planner (unless paused), keeps the planning time and the journal's digests, and now and
// then publishes the progress.
struct LiveSession::Loop {
  const Stopwatch watch;
  double planning_s = 0.0;  ///< planning time since the start or the last reset, pauses out
  double last_tick = 0.0, next_report = 1.0, next_digest = 0.0;
  double next_observe = 0.0, rate_t0 = 0.0;
  std::uint64_t rate_iterations0 = 0, resets_seen = 0;
  double iterations_per_s = 0.0;
  std::uint64_t since_check = 0;
  bool may_step = false;
  bool stepped_by_hand = false;
};

void LiveSession::start_operator() {
  operator_thread_ = std::make_unique<OperatorThread>(
      OperatorModel(checker_, switch_), channel_, options_.operator_rate_hz, &roadmap_distance_);
  operator_thread_->wait_for_first_state(&stop_);
}

bool LiveSession::step_planner(Loop& loop) {
  static constexpr auto kOperator = static_cast<std::size_t>(NodeSource::operator_);
  if (paused_) {
    --steps_requested_;
    loop.stepped_by_hand = true;
  }
  const std::size_t operator_nodes = planner_->stats().nodes_by_source[kOperator];
  status_ = planner_->step();
  ++steps_;
  journal_feed();
  if (planner_->stats().nodes_by_source[kOperator] != operator_nodes)
    measure_latency();
  if (status_ != PlannerStatus::running) {
    if (!options_.stay)
      return false;
    journal_digest(std::nullopt);
  }
  return true;
}

bool LiveSession::keep_time(Loop& loop, double t) {
  if (loop.may_step && !loop.stepped_by_hand)
    loop.planning_s += t - loop.last_tick;
  loop.last_tick = t;
  if (status_ == PlannerStatus::running && loop.planning_s >= spec_.time_limit) {
    status_ = PlannerStatus::timeout;
    if (!options_.stay)
      return false;
    journal_digest(std::nullopt);
  }
  if (t >= loop.next_digest) {
    journal_digest(std::nullopt);
    loop.next_digest = t + options_.digest_every_s;
  }
  if (const Guidance* g = guidance_channel_.latest()) {
    last_guidance_ = *g;
    have_guidance_ = true;
  }
  return true;
}

LiveProgress LiveSession::measure_progress(Loop& loop, double t) {
  if (t - loop.rate_t0 >= 0.5) {
    const std::uint64_t it = planner_->stats().iterations;
    loop.iterations_per_s = static_cast<double>(it - loop.rate_iterations0) / (t - loop.rate_t0);
    loop.rate_iterations0 = it;
    loop.rate_t0 = t;
  }
  LiveProgress p;
  p.stats = planner_->stats();
  p.status = status_;
  p.steps = steps_;
  p.resets = resets_;
  p.paused = paused_;
  p.elapsed_s = loop.planning_s;
  p.iterations_per_s = status_ == PlannerStatus::running && !paused_ ? loop.iterations_per_s : 0.0;
  p.operator_rate_hz = operator_thread_->achieved_rate();
  p.input_latency_s = latency_s_;
  p.input_latency_id = latency_id_;
  return p;
}

void LiveSession::publish_progress(Loop& loop, double t, const ProgressCallback& progress) {
  const bool report = t >= loop.next_report;
  if (!(t >= loop.next_observe || report || loop.stepped_by_hand))
    return;
  const LiveProgress p = measure_progress(loop, t);
  {
    const std::lock_guard lock(pending_mutex_);
    progress_ = p;
  }
  const OperatorInput input = switch_->snapshot().input;
  if (input != input_) {
    journal_->event(steps_, "input " + std::string(to_string(input)));
    input_ = input;
  }
  if (observer_ != nullptr)
    observer_->observe(*this, *planner_);
  loop.next_observe = t + options_.observe_every_s;
  if (report && progress) {
    progress(p);
    loop.next_report = t + 1.0;
  }
}

PlannerStatus LiveSession::run(const ProgressCallback& progress) {
  start_operator();
  Loop loop;
  loop.next_digest = options_.digest_every_s;
  while (!stop_.load(std::memory_order_relaxed)) {
    apply_commands();
    if (resets_ != loop.resets_seen) {
      loop.resets_seen = resets_;
      loop.planning_s = 0.0;
      loop.rate_iterations0 = 0;
    }
    loop.may_step = status_ == PlannerStatus::running && (!paused_ || steps_requested_ > 0);
    loop.stepped_by_hand = false;
    if (loop.may_step) {
      if (!step_planner(loop))
        break;
      // The clock is read every 64 steps (a step is a few microseconds).
      if (++loop.since_check < 64 && !loop.stepped_by_hand && status_ == PlannerStatus::running)
        continue;
    } else {
      show_idle_operator();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    loop.since_check = 0;
    const double t = loop.watch.seconds();
    if (!keep_time(loop, t))
      break;
    publish_progress(loop, t, progress);
  }
  if (status_ == PlannerStatus::running)
    status_ = PlannerStatus::interrupted;
  operator_thread_->stop();
  journal_digest(std::string(to_string(status_)));
  return status_;
}

}  // namespace tandem
