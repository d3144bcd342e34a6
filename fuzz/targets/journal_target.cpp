// Session journals: read, then replayed on the built-in scene 'maze' (the replay refuses a journal
// recorded on another problem, so the recorded seed sessions of fuzz/seeds/journal are on 'maze').
// Accepted means replayed, and the replay reproduced the digests the journal recorded.

#include "fuzz_target.hpp"
#include "scratch_folder.hpp"
#include "tandem/core/error.hpp"
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

}  // namespace

bool journal(std::string_view input) {
  fresh_scratch_folder();
  const std::filesystem::path file = write_scratch_file("session.jsonl", input);
  try {
    const Journal j = read_journal(file);
    if (!j.digests.empty() && j.digests.back().steps > kMaxReplaySteps)
      return false;
    return replay_journal(replay_problem(), j).matched();
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace tandem::fuzz
