// Session journals: read, then replayed on the built-in scene 'maze' (the replay refuses a journal
// recorded on another problem, so the recorded seed sessions of fuzz/seeds/journal are on 'maze').
// Accepted means replayed, and the replay reproduced the digests the journal recorded.

#include "fuzz_target.hpp"
#include "scratch_folder.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/core/error.hpp"
#include "tandem/planning/planner_settings.hpp"
#include "tandem/scene/problem_loader.hpp"
#include "tandem/session/journal.hpp"
#include "tandem/session/replay.hpp"

namespace tandem::fuzz {
namespace {

/// A journal claims how long its session ran, and a replay runs that long: the target replays
/// only journals of sessions short enough to keep the fuzzing loop fast (the seeds' are).
constexpr std::uint64_t kMaxReplaySteps = 5000;

const Problem& replay_problem() {
  static const Problem problem = load_problem("maze");
  return problem;
}

/// The problem's checker with the distance grid the planners' default settings use, built once
/// (under the sanitizers building it takes seconds; every replay clones it).
const CollisionChecker& prepared_checker() {
  static const CollisionChecker checker = [] {
    CollisionChecker c(replay_problem().scene);
    const MotionValidator validator(replay_problem().space, c,
                                    validation_settings(PlannerSettings{}));
    return c;
  }();
  return checker;
}

}  // namespace

void prepare_journal() {
  (void)prepared_checker();
}

bool journal(std::string_view input) {
  fresh_scratch_folder();
  const std::filesystem::path file = write_scratch_file("session.jsonl", input);
  try {
    const Journal j = read_journal(file);
    if (!j.digests.empty() && j.digests.back().steps > kMaxReplaySteps)
      return false;
    return replay_journal(replay_problem(), j, {}, {}, &prepared_checker()).matched();
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace tandem::fuzz
