// A session in virtual time: stepped by the caller, with any operator, journaled so that the
// replay rebuilds the same trees.

#include "tandem/session/virtual_session.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/problems.hpp"
#include "support/runs.hpp"
#include "support/test_support.hpp"
#include "tandem/runs/run.hpp"
#include "tandem/session/replay.hpp"

namespace tandem {
namespace {

/// An operator that is not a function of time: it remembers where it was asked last and moves
/// from there a fixed share toward the goal, with a drift that depends on how often it was asked.
class WanderingOperator final : public OperatorSource {
 public:
  WanderingOperator(const SE3Space& space, Config start, Config goal)
      : space_(space), at_(std::move(start)), goal_(std::move(goal)) {}
  DeviceReading read(double t) const override {
    ++calls_;
    Config next = space_.interpolate(at_, goal_, 0.05);
    next.t.z() += 0.02 * static_cast<double>(calls_ % 5) - 0.04;
    at_ = next;
    (void)t;
    return {next};
  }
  double end_time() const override { return 1e9; }
  std::string describe() const override { return "a wandering test operator"; }

 private:
  const SE3Space& space_;
  mutable Config at_;
  Config goal_;
  mutable std::uint64_t calls_ = 0;
};

ReplayResult replay_file(const Problem& problem, const std::filesystem::path& file) {
  return replay_journal(problem, read_journal(file));
}

TEST(VirtualSession, IsTheRunOfAnExperimentAndItsJournalReplays) {
  const Problem problem = test::detour_problem();
  RunSpec spec = test::live_spec(3);
  test::TempDir dir;
  VirtualSessionOptions options;
  options.journal = dir.path() / "s.jsonl";
  options.digest_every = 200;
  PlannerStatus status = PlannerStatus::running;
  std::string digest;
  {
    VirtualSession session(problem, spec, nullptr, options);
    EXPECT_EQ(session.step(10), PlannerStatus::running);
    EXPECT_EQ(session.steps(), 10u);
    ASSERT_NE(session.operator_state(), nullptr);
    status = session.run();
    digest = format_digest(tree_digest(session.planner().trees()));
  }
  ASSERT_EQ(status, PlannerStatus::solved);
  // The same run as an experiment's (same seed, same operator, same trees).
  spec.settings.threads = 1;
  EXPECT_EQ(format_digest(execute_run(problem, spec).tree_digest), digest);
  const ReplayResult replay = replay_file(problem, options.journal);
  EXPECT_TRUE(replay.matched());
  EXPECT_GT(replay.digests_checked, 1u);
  EXPECT_EQ(replay.status, PlannerStatus::solved);
  EXPECT_EQ(replay.digest, digest);
}

TEST(VirtualSession, AnOperatorThatIsNotAFunctionOfTimeReplaysFromTheJournal) {
  const Problem problem = test::detour_problem();
  const RunSpec spec = test::live_spec(5);
  test::TempDir dir;
  VirtualSessionOptions options;
  options.journal = dir.path() / "s.jsonl";
  std::string digest;
  std::uint64_t steps = 0;
  {
    auto op = std::make_shared<WanderingOperator>(problem.space, problem.start, problem.goal);
    VirtualSession session(problem, spec, op, options);
    EXPECT_EQ(session.step(100), PlannerStatus::running);
    InteractionSettings contact = spec.settings.interaction;
    contact.alpha = 0.9;
    session.set_interaction(contact);
    EXPECT_EQ(session.run(), PlannerStatus::solved);
    digest = format_digest(tree_digest(session.planner().trees()));
    steps = session.steps();
  }
  const ReplayResult replay = replay_file(problem, options.journal);
  EXPECT_TRUE(replay.matched());
  EXPECT_EQ(replay.steps, steps);
  EXPECT_EQ(replay.digest, digest);
  // A different operator gives different trees: the replay is not trivially equal.
  VirtualSession other(problem, spec, nullptr, {});
  (void)other.step(steps);
  EXPECT_NE(format_digest(tree_digest(other.planner().trees())), digest);
}

}  // namespace
}  // namespace tandem
