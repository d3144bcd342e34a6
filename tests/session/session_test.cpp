// Live sessions: the journal, the planner and operator threads, and exact replay.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/session/live_session.hpp"
#include "tandem/session/replay.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

/// The wall with a gap, start and goal on either side away from the gap, and a guide through it.
Problem detour_problem() {
  Problem p = test::wall_with_gap_problem();
  p.start.t = {-2, 2, 0};
  p.goal.t = {2, 2, 0};
  p.guide = {p.start, Config{}, Config{}, p.goal};
  p.guide[1].t = {-0.8, 0.0, 0.0};
  p.guide[2].t = {0.8, 0.0, 0.0};
  return p;
}

RunSpec live_spec(std::uint64_t seed) {
  RunSpec spec = default_spec("interactive-contact", {});
  spec.settings.seed = seed;
  spec.settings.extend = ExtendMode::last_valid;
  spec.settings.interaction.alpha = 0.3;
  spec.operator_name = "experienced";
  spec.operator_seed = seed;
  spec.time_limit = 20.0;
  return spec;
}

TEST(Journal, WritesAndReadsBackEveryRecordExactly) {
  const Problem problem = detour_problem();
  test::TempDir dir;
  const auto file = dir.path() / "s.jsonl";
  JournalHeader h;
  h.problem = "detour";
  h.problem_digest = format_digest(problem_digest(problem));
  h.mode = "interactive-contact";
  h.settings.seed = 42;
  h.settings.interaction.alpha = 0.37;
  h.settings.interaction.sampling = IrrtSampling::path_cs;
  h.operator_description = "someone";
  h.started = "2026-12-01T00:00:00Z";
  OperatorState s;
  s.sequence = 7;
  s.time = 0.1 + 0.2;  // not a short decimal
  s.pace = 1.0 / 3.0;
  s.device.q_device.t = {std::acos(-1.0), -1e-17, 2.5};
  s.device.q_device.q =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  s.device.velocity << 1, 2, 3, 4, 5, 6.000000000000001;
  s.device.buttons = 5;
  {
    JournalWriter w(file, h);
    w.operator_state(12, s);
    InteractionSettings changed = h.settings.interaction;
    changed.alpha = 0.9;
    w.params(100, changed);
    w.digest({200, 199, 31, "00000000deadbeef", std::string("solved")});
  }
  const Journal j = read_journal(file);
  EXPECT_FALSE(j.torn);
  EXPECT_EQ(j.header.problem, "detour");
  EXPECT_EQ(j.header.settings.seed, 42u);
  EXPECT_EQ(j.header.settings.interaction.alpha, 0.37);
  EXPECT_EQ(j.header.settings.interaction.sampling, IrrtSampling::path_cs);
  ASSERT_EQ(j.operator_states.size(), 1u);
  const auto& r = j.operator_states[0];
  EXPECT_EQ(r.iteration, 12u);
  EXPECT_EQ(r.sequence, 7u);
  EXPECT_EQ(r.time, s.time);
  EXPECT_EQ(r.pace, s.pace);
  EXPECT_TRUE(r.device.q_device == s.device.q_device);  // bit for bit
  EXPECT_EQ(r.device.velocity, s.device.velocity);
  EXPECT_EQ(r.device.buttons, 5u);
  ASSERT_EQ(j.params.size(), 1u);
  EXPECT_EQ(j.params[0].steps, 100u);
  EXPECT_EQ(j.params[0].settings.alpha, 0.9);
  ASSERT_EQ(j.digests.size(), 1u);
  EXPECT_EQ(j.digests[0].end_status, "solved");
  EXPECT_EQ(j.digests[0].digest, "00000000deadbeef");
}

TEST(Journal, ATornLastLineIsIgnoredAndAMalformedLineNamed) {
  test::TempDir dir;
  JournalHeader h;
  h.problem = "p";
  const auto file = dir.path() / "s.jsonl";
  { JournalWriter w(file, h); }
  const std::string header = read_text_file(file);
  const auto torn = dir.write("torn.jsonl", header + "{\"op\":3,\"seq\":1,\"t\":0.5,\"pa");
  EXPECT_TRUE(read_journal(torn).torn);
  const auto bad = dir.write("bad.jsonl", header + "{\"op\":3}\n");
  try {
    read_journal(bad);
    FAIL() << "a malformed record was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("bad.jsonl"));
    EXPECT_THAT(e.what(), HasSubstr("line 2"));
  }
  const auto other = dir.write("other.jsonl", "{\"hello\":1}\n");
  EXPECT_THROW(read_journal(other), InputError);
  EXPECT_THROW(read_journal(dir.path() / "missing.jsonl"), InputError);
}

TEST(LiveSession, ReplaysToTheIdenticalTree) {
  const Problem problem = detour_problem();
  test::TempDir dir;
  LiveOptions options;
  options.journal = dir.path() / "live.jsonl";
  options.operator_rate_hz = 2000.0;
  options.digest_every_s = 0.05;
  RunSpec spec = live_spec(3);
  spec.settings.interaction.alpha = 0.0;  // the operator alone: slow through the gap
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
  LiveOptions options;
  options.journal = dir.path() / "live.jsonl";
  options.digest_every_s = 0.01;
  RunSpec spec = live_spec(4);
  spec.settings.interaction.alpha = 0.0;  // the operator alone: slow, so there is time to record
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
  EXPECT_THROW(replay_journal(other, read_journal(file)), InputError);
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
  LiveOptions options;
  options.journal = dir.path() / "live.jsonl";
  options.digest_every_s = 0.02;
  options.stay = true;  // as with the viewer: stays after solving until stopped
  options.spacemouse = false;
  RunSpec spec = live_spec(5);
  spec.settings.interaction.alpha = 0.0;
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

TEST(SpaceNav, SaysWhyWhenTheDaemonIsAbsent) {
  std::string why;
  const std::unique_ptr<SpaceNav> nav = SpaceNav::open(&why);
  if (nav != nullptr)
    GTEST_SKIP() << "spacenavd is running here (" << nav->name() << ")";
  EXPECT_THAT(why, HasSubstr("spacenavd is not running"));
  EXPECT_THAT(why, HasSubstr("browser"));
}

TEST(OperatorSwitch, TakesOverWhereThePartIsAndKeepsItInTheSpace) {
  const Problem problem = detour_problem();
  RunSpec spec = live_spec(1);
  const auto simulated = make_operator(problem, spec, OperatorClock::seconds);
  OperatorSwitch input(problem.space, simulated, problem.start);
  const DeviceReading a = input.read(0.5);
  EXPECT_EQ(a.q_device, simulated->read(0.5).q_device) << "the simulated operator has the part";
  std::string why;
  EXPECT_FALSE(input.select(OperatorInput::spacemouse, &why));
  EXPECT_THAT(why, HasSubstr("spacenavd"));
  ASSERT_TRUE(input.select(OperatorInput::browser));
  EXPECT_EQ(input.read(5.0).q_device, a.q_device) << "the person takes the part where it was";
  Config far = problem.start;
  far.t = {1e6, -1e6, 0.0};
  far.q = Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0);  // not unit
  input.set_pose(far, 3);
  const DeviceReading b = input.read(5.1);
  EXPECT_TRUE(problem.space.satisfies_bounds(b.q_device)) << "clamped to the bounds";
  EXPECT_NEAR(b.q_device.q.norm(), 1.0, 1e-12);
  EXPECT_EQ(b.input_id, 3u);
  EXPECT_TRUE(input.input_time(3).has_value());
  EXPECT_FALSE(input.input_time(2).has_value());

  OperatorSwitch alone(problem.space, nullptr, problem.start);
  EXPECT_EQ(alone.snapshot().input, OperatorInput::browser);
  EXPECT_EQ(alone.read(1.0).q_device, problem.start) << "without an operator the part waits";
  EXPECT_FALSE(alone.select(OperatorInput::simulated, &why));
}

}  // namespace
}  // namespace tandem
