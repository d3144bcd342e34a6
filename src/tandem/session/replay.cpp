#include "tandem/session/replay.hpp"

#include "tandem/core/error.hpp"
#include "tandem/interaction/interaction.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/runs/run.hpp"

namespace tandem {

namespace {

/// Throws InputError if the journal was not recorded on `problem`, or not by a planner that takes
/// an operator.
void require_replayable(const Problem& problem, const JournalHeader& h) {
  if (format_digest(problem_digest(problem)) != h.problem_digest) {
    throw InputError(h.problem, "is not the problem this session was recorded on (its digest is " +
                                    format_digest(problem_digest(problem)) + ", the journal's " +
                                    h.problem_digest + ")");
  }
  const PlannerEntry* entry = find_planner(h.mode);
  if (entry == nullptr || !entry->uses_operator) {
    throw InputError(h.problem,
                     "the journal's mode '" + h.mode + "' is not a planner that takes an operator");
  }
}

/// The operator states as the live planner saw them, one list per planner (the user may have
/// started over); the nearest obstacle and the contact frame are recomputed from q_device, as the
/// operator thread computed them.
std::vector<std::vector<FeedRecord>> operator_segments(const Journal& journal,
                                                       const CollisionChecker& checker) {
  OperatorModel model(checker, nullptr);
  std::vector<std::vector<FeedRecord>> segments(journal.resets.size() + 1);
  for (const Journal::OperatorRecord& r : journal.operator_states) {
    segments.at(r.segment).push_back(
        {r.iteration, model.observe(r.device, r.time, r.pace, r.sequence)});
  }
  return segments;
}

}  // namespace

ReplayResult replay_journal(const Problem& problem, const Journal& journal,
                            const ReplayStep& on_step, const std::function<void()>& on_reset,
                            const CollisionChecker* prepared) {
  const JournalHeader& h = journal.header;
  require_replayable(problem, h);
  CollisionChecker checker =
      prepared != nullptr ? prepared->clone() : CollisionChecker(problem.scene);
  std::vector<std::vector<FeedRecord>> segments = operator_segments(journal, checker);
  InteractionParameters parameters(h.settings.interaction);
  MotionValidator validator(problem.space, checker);
  std::unique_ptr<ReplayFeed> feed;
  Interaction interaction{nullptr, &parameters};
  std::unique_ptr<Planner> planner;
  auto start_planner = [&](std::size_t segment) {
    planner.reset();
    feed = std::make_unique<ReplayFeed>(std::move(segments[segment]));
    interaction.feed = feed.get();
    planner =
        make_planner(h.mode, validator, problem.start, problem.goal, h.settings, &interaction);
  };
  start_planner(0);

  ReplayResult result;
  const std::uint64_t last_step = journal.digests.empty() ? 0 : journal.digests.back().steps;
  std::size_t next_params = 0, next_digest = 0, next_reset = 0;
  // The digests recorded so far of the planner running now (the live session records them while
  // it waits, too: paused, or after a reset, before the new planner's first step).
  auto check_digests = [&] {
    while (next_digest < journal.digests.size() &&
           journal.digests[next_digest].segment == next_reset &&
           journal.digests[next_digest].steps <= result.steps) {
      const JournalDigest& d = journal.digests[next_digest++];
      ++result.digests_checked;
      if (!result.mismatch_at && format_digest(tree_digest(planner->trees())) != d.digest)
        result.mismatch_at = d.steps;
    }
  };
  PlannerStatus status = PlannerStatus::running;
  check_digests();
  while (result.steps < last_step) {
    while (next_reset < journal.resets.size() && journal.resets[next_reset] == result.steps) {
      start_planner(++next_reset);
      status = PlannerStatus::running;
      if (on_reset)
        on_reset();
      check_digests();
    }
    while (next_params < journal.params.size() &&
           journal.params[next_params].steps == result.steps) {
      parameters.set(journal.params[next_params++].settings);
    }
    if (status == PlannerStatus::running) {
      status = planner->step();
      ++result.steps;
    } else if (next_reset < journal.resets.size()) {
      result.steps = journal.resets[next_reset];  // the live session idled until the reset
    } else {
      break;
    }
    if (on_step)
      on_step(*planner, feed->current(), false);
    check_digests();
  }
  if (on_step)
    on_step(*planner, feed->current(), true);
  result.status = status;
  result.stats = planner->stats();
  result.digest = format_digest(tree_digest(planner->trees()));
  result.solution = planner->solution();
  return result;
}

}  // namespace tandem
