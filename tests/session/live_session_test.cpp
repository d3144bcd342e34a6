// Live sessions: the planner and operator threads, tuning, pause, step, reset and takeover while
// running, and exact replay of the journal.

#include "tandem/session/live_session.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <optional>
#include <thread>

#include "support/problems.hpp"
#include "support/runs.hpp"
#include "tandem/core/text.hpp"
#include "tandem/session/replay.hpp"

namespace tandem {
namespace {

using test::detour_problem;
using test::live_spec;
using ::testing::HasSubstr;

/// Options of a session journaled in `dir`, with a tree digest every `digest_every_s` seconds.
LiveOptions journaled(const test::TempDir& dir, double digest_every_s) {
  LiveOptions options;
  options.journal = dir.path() / "live.jsonl";
  options.digest_every_s = digest_every_s;
  return options;
}

/// Journaled options as the viewer runs a session: it stays after solving until stopped, without
/// a SpaceMouse; `paused`: it starts paused.
LiveOptions as_viewer(const test::TempDir& dir, double digest_every_s, bool paused) {
  LiveOptions options = journaled(dir, digest_every_s);
  options.stay = true;
  options.spacemouse = false;
  options.start_paused = paused;
  return options;
}

/// A live run of seed `seed` where the operator alone grows the tree: slow through the gap, so
/// there is time to tune, pause and record.
RunSpec operator_alone(std::uint64_t seed) {
  RunSpec spec = live_spec(seed);
  spec.settings.interaction.alpha = 0.0;
  return spec;
}

TEST(LiveSession, ReplaysToTheIdenticalTree) {
  const Problem problem = detour_problem();
  test::TempDir dir;
  LiveOptions options = journaled(dir, 0.05);
  options.operator_rate_hz = 2000.0;
  RunSpec spec = operator_alone(3);
  LiveSession session(problem, spec, options);
  // Tuning from another thread while the planner runs: the computer gets authority too. The
  // change is journaled with the step after which it applied, and replayed there.
  std::thread tuner([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    InteractionSettings s = spec.settings.interaction;
    s.contact = true;
    s.alpha = 0.5;
    session.set_interaction(s);
  });
  const PlannerStatus status = session.run();
  tuner.join();
  EXPECT_EQ(status, PlannerStatus::solved);
  const std::string live_digest = format_digest(tree_digest(session.planner().trees()));

  const Journal journal = read_journal(options.journal);
  EXPECT_FALSE(journal.operator_states.empty());
  ASSERT_EQ(journal.params.size(), 1u) << "the session solved before it was tuned";
  EXPECT_GT(journal.params[0].steps, 0u);
  EXPECT_EQ(journal.params[0].settings.alpha, 0.5);
  ASSERT_FALSE(journal.digests.empty());
  EXPECT_EQ(journal.digests.back().end_status, "solved");
  EXPECT_EQ(journal.digests.back().digest, live_digest);
  const ReplayResult replay = replay_journal(problem, journal);
  EXPECT_TRUE(replay.matched());
  EXPECT_EQ(replay.status, PlannerStatus::solved);
  EXPECT_EQ(replay.digest, live_digest);
  EXPECT_EQ(replay.stats.nodes, session.planner().stats().nodes);
}

TEST(LiveSession, AKilledSessionReplaysUpToItsLastRecord) {
  const Problem problem = detour_problem();
  test::TempDir dir;
  LiveOptions options = journaled(dir, 0.01);
  RunSpec spec = operator_alone(4);
  spec.time_limit = 0.5;
  LiveSession session(problem, spec, options);
  session.run();
  // Cut the journal in the middle of a line after its second digest, as a kill would.
  const std::string text = read_text_file(options.journal);
  std::size_t digests = 0, cut = std::string::npos;
  for (std::size_t pos = text.find("{\"digest\""); pos != std::string::npos;
       pos = text.find("{\"digest\"", pos + 1)) {
    if (++digests == 2)
      cut = text.find('\n', pos) + 8;
  }
  ASSERT_NE(cut, std::string::npos) << "the session recorded fewer than two digests";
  const auto killed = dir.write("killed.jsonl", text.substr(0, cut));
  const Journal journal = read_journal(killed);
  EXPECT_TRUE(journal.torn);
  ASSERT_EQ(journal.digests.size(), 2u);
  const ReplayResult replay = replay_journal(problem, journal);
  EXPECT_TRUE(replay.matched());
  EXPECT_EQ(replay.steps, journal.digests.back().steps);
}

/// Waits (up to 10 s) until `done` holds, checking every millisecond.
template <class F>
bool eventually(F done) {
  for (int k = 0; k < 10000; ++k) {
    if (done())
      return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

TEST(LiveSession, PauseStepResetAndTakeoverReplayToTheIdenticalTree) {
  const Problem problem = detour_problem();
  test::TempDir dir;
  const LiveOptions options = as_viewer(dir, 0.02, false);
  RunSpec spec = operator_alone(5);
  LiveSession session(problem, spec, options);
  PlannerStatus status = PlannerStatus::running;
  std::thread planner([&] { status = session.run(); });

  ASSERT_TRUE(eventually([&] { return session.progress().stats.nodes > 3; }));
  const std::uint64_t running_at = session.progress().steps;
  session.step_once();  // while running: ignored, not kept for later
  ASSERT_TRUE(eventually([&] { return session.progress().steps > running_at; }));
  session.pause();
  ASSERT_TRUE(eventually([&] { return session.progress().paused; }));
  const std::uint64_t paused_at = session.progress().steps;
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_EQ(session.progress().steps, paused_at) << "a paused session steps";
  session.step_once();
  session.step_once();
  EXPECT_TRUE(eventually([&] { return session.progress().steps == paused_at + 2; }));
  // A person takes over from the simulated operator where the part is, and moves it.
  Config held = problem.start;
  held.t.y() += 0.2;
  session.operator_input().set_pose(held, 7);
  EXPECT_EQ(session.operator_input().snapshot().input, OperatorInput::browser);
  session.reset();
  session.resume();
  ASSERT_TRUE(eventually([&] { return session.progress().resets == 1; }));
  ASSERT_TRUE(session.operator_input().select(OperatorInput::simulated));
  EXPECT_TRUE(eventually([&] { return session.progress().stats.nodes > 3; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  session.stop();
  planner.join();
  const std::string live_digest = format_digest(tree_digest(session.planner().trees()));

  const Journal journal = read_journal(options.journal);
  ASSERT_EQ(journal.resets.size(), 1u);
  EXPECT_GE(journal.resets[0], paused_at + 2);
  std::string events;
  for (const Journal::Event& e : journal.events)
    events += e.what + ";";
  EXPECT_THAT(events, HasSubstr("input simulated;"));
  EXPECT_THAT(events, HasSubstr("pause;"));
  EXPECT_THAT(events, HasSubstr("step "));  // the two steps, in one record or two
  EXPECT_LT(events.find("pause;"), events.find("step "))
      << "a step asked for while running counted";
  EXPECT_THAT(events, HasSubstr("input browser;"));
  EXPECT_THAT(events, HasSubstr("resume;"));
  EXPECT_EQ(journal.digests.back().digest, live_digest);
  EXPECT_EQ(journal.digests.back().end_status, std::string(to_string(status)));
  std::size_t restarts = 0;
  const ReplayResult replay = replay_journal(problem, journal, {}, [&] { ++restarts; });
  EXPECT_EQ(restarts, 1u);
  EXPECT_TRUE(replay.matched()) << "mismatch at step " << replay.mismatch_at.value_or(0);
  EXPECT_EQ(replay.digest, live_digest);
}

// A session started paused, and the viewer's pause, reset, ... resume: the journal records digests
// of the empty tree while the session waits, at step 0 and at the step count of the reset. The
// replay compares them with the planner before its first step (after a reset, the new planner, not
// the old one that ran up to that step).
TEST(LiveSession, DigestsRecordedWhilePausedAtTheStartAndAfterAResetReplay) {
  const Problem problem = detour_problem();
  test::TempDir dir;
  const LiveOptions options = as_viewer(dir, 0.005, true);
  RunSpec spec = operator_alone(6);
  LiveSession session(problem, spec, options);
  std::thread planner([&] { session.run(); });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  session.resume();
  ASSERT_TRUE(eventually([&] { return session.progress().stats.nodes > 3; }));
  session.pause();
  ASSERT_TRUE(eventually([&] { return session.progress().paused; }));
  session.reset();
  ASSERT_TRUE(eventually([&] { return session.progress().resets == 1; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // ten digest periods, paused
  session.resume();
  EXPECT_TRUE(eventually([&] { return session.progress().stats.nodes > 3; }));
  session.stop();
  planner.join();

  const Journal journal = read_journal(options.journal);
  ASSERT_EQ(journal.resets.size(), 1u);
  const std::uint64_t reset_at = journal.resets[0];
  std::size_t at_reset = 0;
  for (const JournalDigest& d : journal.digests)
    at_reset += d.steps == reset_at ? 1 : 0;
  ASSERT_GE(at_reset, 2u) << "digests of the old tree and of the new one, both at the reset";
  ASSERT_EQ(journal.digests.front().steps, 0u) << "no digest while paused at the start";
  const ReplayResult replay = replay_journal(problem, journal);
  EXPECT_TRUE(replay.matched()) << "mismatch at step " << replay.mismatch_at.value_or(0);
  EXPECT_EQ(replay.digest, format_digest(tree_digest(session.planner().trees())));
}

/// Keeps the operator's q_device as the session showed it last (observe() on the planner thread).
class ShownOperator final : public LiveObserver {
 public:
  void observe(const LiveSession& session, const Planner& /*planner*/) override {
    const std::lock_guard lock(mutex_);
    if (const OperatorState* s = session.operator_state())
      shown_ = s->device.q_device;
  }
  void restarted() override {}
  bool shows(const Config& q) const {
    const std::lock_guard lock(mutex_);
    return shown_ && (shown_->t - q.t).norm() < 1e-12 && shown_->q.isApprox(q.q, 1e-12);
  }

 private:
  mutable std::mutex mutex_;
  std::optional<Config> shown_;
};

// A viewer shows the operator where the person put the part, also while the planner does not step
// (paused, or solved in a session that stays): the page follows the operator the session shows,
// and would otherwise put the part back where the planner last saw it. What is only shown is not
// journaled: the session still replays to the identical tree.
TEST(LiveSession, WhileThePlannerDoesNotStepTheOperatorShownIsWhereThePersonPutIt) {
  const Problem problem = detour_problem();
  test::TempDir dir;
  const LiveOptions options = as_viewer(dir, 0.05, true);
  RunSpec spec = live_spec(8);
  spec.settings.interaction.alpha = 1.0;  // the computer alone: solves soon
  LiveSession session(problem, spec, options);
  ShownOperator shown;
  session.set_observer(&shown);
  std::thread planner([&] { session.run(); });

  Config held = problem.start;
  held.t.y() += 0.2;
  session.operator_input().set_pose(held, 1);
  EXPECT_TRUE(eventually([&] { return shown.shows(held); })) << "paused";
  EXPECT_EQ(session.progress().steps, 0u);
  session.resume();
  ASSERT_TRUE(eventually([&] { return session.progress().status == PlannerStatus::solved; }));
  const std::uint64_t solved_at = session.progress().steps;
  held.t.x() += 0.1;
  session.operator_input().set_pose(held, 2);
  EXPECT_TRUE(eventually([&] { return shown.shows(held); })) << "solved";
  session.stop();
  planner.join();
  session.set_observer(nullptr);
  EXPECT_EQ(session.steps(), solved_at);

  const ReplayResult replay = replay_journal(problem, read_journal(options.journal));
  EXPECT_TRUE(replay.matched()) << "mismatch at step " << replay.mismatch_at.value_or(0);
  EXPECT_EQ(replay.status, PlannerStatus::solved);
  EXPECT_EQ(replay.digest, format_digest(tree_digest(session.planner().trees())));
}

}  // namespace
}  // namespace tandem
