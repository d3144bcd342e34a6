// Live sessions: the journal, the planner and operator threads, and exact replay.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"
#include "tandem/io/text.hpp"
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
  RunSpec spec;
  spec.mode = PlannerMode::interactive_contact;
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

}  // namespace
}  // namespace tandem
