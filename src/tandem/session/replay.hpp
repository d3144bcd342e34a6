#pragma once
// Replays a session journal: the same planner, seed and settings, fed the operator states the live
// planner used, at the iterations it used them, with the same parameter changes after the same
// steps — in virtual time, as fast as the machine goes. The trees come out identical; the digests
// the journal recorded on the way check that they do.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "tandem/planning/planner.hpp"
#include "tandem/scene/problem.hpp"
#include "tandem/session/journal.hpp"

namespace tandem {

struct ReplayResult {
  PlannerStatus status = PlannerStatus::running;
  std::uint64_t steps = 0;
  PlannerStats stats;
  std::string digest;  ///< of the trees at the end of the replay
  std::size_t digests_checked = 0;
  /// The first recorded digest the replay did not reproduce (its steps), if any.
  std::optional<std::uint64_t> mismatch_at;
  std::vector<Config> solution;
  bool matched() const { return !mismatch_at && digests_checked > 0; }
};

/// Throws InputError if the journal's problem digest is not the problem's, or its mode is unknown.
/// `on_step`, if given, is called after every step with the planner and the operator state it used
/// last (a viewer can follow the replay), and once more with `last` set when the replay ends;
/// `on_reset` when the replay starts the planner over where the user did. `prepared`, if given, is a
/// checker of the problem already prepared (its distance grid built): the replay clones it rather
/// than build the grid again.
using ReplayStep = std::function<void(const Planner&, const OperatorState*, bool last)>;
ReplayResult replay_journal(const Problem& problem, const Journal& journal,
                            const ReplayStep& on_step = {},
                            const std::function<void()>& on_reset = {},
                            const CollisionChecker* prepared = nullptr);

}  // namespace tandem
