// The session journal: every record read back exactly, a torn last line ignored.

#include "tandem/session/journal.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/problems.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"

namespace tandem {
namespace {

using test::detour_problem;
using ::testing::HasSubstr;

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
  h.take_out.part = "housing/peg";
  h.take_out.margin = 0.1 + 0.2;
  h.take_out.seat_tolerance = 1.0 / 3.0;
  h.take_out.cad = {1e-5, 0.25};
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
  EXPECT_EQ(j.header.take_out.part, "housing/peg");  // and how it was taken out, to the bit
  EXPECT_EQ(j.header.take_out.margin, h.take_out.margin);
  EXPECT_EQ(j.header.take_out.seat_tolerance, h.take_out.seat_tolerance);
  EXPECT_EQ(j.header.take_out.cad.linear_deflection, 1e-5);
  EXPECT_EQ(j.header.take_out.cad.angular_deflection, 0.25);
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

/// The header line a JournalWriter writes for the problem "p" (written in `dir`).
std::string header_line(const test::TempDir& dir) {
  JournalHeader h;
  h.problem = "p";
  const auto file = dir.path() / "s.jsonl";
  { JournalWriter w(file, h); }
  return read_text_file(file);
}

TEST(Journal, ATornLastLineIsIgnoredAndAMalformedLineNamed) {
  test::TempDir dir;
  const std::string header = header_line(dir);
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
  EXPECT_THAT(test::error_message<InputError>([&] { return read_journal(other); }),
              HasSubstr("other.jsonl: not a tandem session journal (no header line)"));
  EXPECT_THAT(
      test::error_message<InputError>([&] { return read_journal(dir.path() / "missing.jsonl"); }),
      HasSubstr("missing.jsonl: no such file"));
}

// nlohmann casts a float to an unsigned type without a check (undefined out of range; found by the
// journal fuzz target): a whole-number field that is not one is the journal's error.
TEST(Journal, RefusesAFloatOrNegativeWhereAWholeNumberGoes) {
  test::TempDir dir;
  const std::string header = header_line(dir);
  for (const std::string op : {"2.01845e+21", "-3", "1.5"}) {
    const auto bad = dir.write("op.jsonl", header + "{\"op\":" + op +
                                               ",\"seq\":1,\"t\":0.5,\"pace\":0.5,\"q\":[0,0,0,"
                                               "0,0,0,1],\"v\":[0,0,0,0,0,0],\"b\":0}\n");
    EXPECT_THAT(test::error_message<InputError>([&] { return read_journal(bad); }),
                HasSubstr("'op' must be a whole number from 0 to"))
        << op;
  }
}

// A journal's poses are read bit for bit, not normalised: one that config_json did not write is
// refused (a huge quaternion made FCL's distance assert in the replay; journal fuzz target).
TEST(Journal, RefusesAPoseThatIsNotAUnitQuaternion) {
  test::TempDir dir;
  const std::string header = header_line(dir);
  for (const std::string q : {"0,0,0,0,0,-2.1e306,1", "0,0,0,0,0,0,2", "0,0,0,0,0,0,0"}) {
    const auto bad = dir.write("q.jsonl", header +
                                              "{\"op\":1,\"seq\":1,\"t\":0.5,\"pace\":0.5,"
                                              "\"q\":[" +
                                              q + "],\"v\":[0,0,0,0,0,0],\"b\":0}\n");
    EXPECT_THAT(test::error_message<InputError>([&] { return read_journal(bad); }),
                HasSubstr("line 2: a pose is x y z and a unit quaternion"))
        << q;
  }
}

}  // namespace
}  // namespace tandem
