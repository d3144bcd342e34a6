// Replaying a session's journal.

#include "tandem/session/replay.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/problems.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

using test::detour_problem;
using ::testing::HasSubstr;

TEST(Replay, RefusesAnotherProblem) {
  const Problem problem = detour_problem();
  test::TempDir dir;
  JournalHeader h;
  h.problem = "detour";
  h.problem_digest = format_digest(problem_digest(problem));
  h.mode = "interactive";
  const auto file = dir.path() / "s.jsonl";
  {
    JournalWriter w(file, h);
    w.digest({1, 0, 2, "0", std::nullopt});
  }
  Problem other = problem;
  other.goal.t.x() += 0.1;
  EXPECT_NE(problem_digest(other), problem_digest(problem));
  EXPECT_THAT(
      test::error_message<InputError>([&] { return replay_journal(other, read_journal(file)); }),
      HasSubstr("detour: is not the problem this session was recorded on"));
}

}  // namespace
}  // namespace tandem
