// Operator traces: the file format and their player.

#include "tandem/operators/trace.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/problems.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

const SE3Space& space() {
  return test::room_space();
}

TEST(Trace, RoundTripsExactly) {
  Trace trace;
  trace.clock = OperatorClock::seconds;
  Rng rng(4);
  for (int i = 0; i < 50; ++i)
    trace.samples.push_back(
        {0.01 * i, space().sample_uniform(rng), static_cast<std::uint32_t>(i % 3)});
  const Trace back = parse_trace(format_trace(trace), "t");
  EXPECT_EQ(back.clock, OperatorClock::seconds);
  ASSERT_EQ(back.samples.size(), trace.samples.size());
  for (std::size_t i = 0; i < back.samples.size(); ++i) {
    EXPECT_EQ(back.samples[i].t, trace.samples[i].t);
    EXPECT_TRUE(back.samples[i].q == trace.samples[i].q);
    EXPECT_EQ(back.samples[i].buttons, trace.samples[i].buttons);
  }
}

TEST(TracePlayer, InterpolatesAndHoldsTheLastSample) {
  Trace trace;
  Config a, b;
  a.t = {0, 0, 1};
  b.t = {2, 0, 1};
  trace.samples = {{0, a, 0}, {100, b, 1}};
  const TracePlayer player(space(), trace);
  EXPECT_NEAR(player.read(50).q_device.t.x(), 1.0, 1e-12);
  EXPECT_EQ(player.read(50).buttons, 0u);
  EXPECT_EQ(player.read(100).buttons, 1u);
  EXPECT_NEAR(player.read(50).velocity.x(), 0.02, 1e-12);
  EXPECT_TRUE(player.read(1e6).q_device == b);
  EXPECT_EQ(player.end_time(), 100.0);
}

std::string trace_error(const std::string& text) {
  try {
    parse_trace(text, "bad.trace");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted " << text;
  return {};
}

TEST(Trace, ReportsMalformedFiles) {
  const std::string head = "# tandem operator trace 1\n# clock: ticks\n";
  EXPECT_THAT(trace_error("0 0 0 0 0 0 0 1 0\n"), HasSubstr("not a tandem operator trace"));
  EXPECT_THAT(trace_error("# tandem operator trace 1\n0 0 0 0 0 0 0 1 0\n"),
              HasSubstr("'# clock:' line must come"));
  EXPECT_THAT(trace_error(head + "0 0 0 0 0 0 0 1\n"), HasSubstr("bad.trace:3: expected 9 fields"));
  EXPECT_THAT(trace_error(head + "0 0 x 0 0 0 0 1 0\n"), HasSubstr("'x' is not a finite number"));
  EXPECT_THAT(trace_error(head + "0 0 0 0 0 0 0 0 0\n"), HasSubstr("the quaternion is zero"));
  EXPECT_THAT(trace_error(head + "5 0 0 0 0 0 0 1 0\n4 0 0 0 0 0 0 1 0\n"),
              HasSubstr("bad.trace:4: time goes backwards"));
  EXPECT_THAT(trace_error(head + "0 0 0 0 0 0 0 1 -1\n"), HasSubstr("buttons"));
  EXPECT_THAT(trace_error(head), HasSubstr("no samples"));
  EXPECT_THAT(trace_error("# tandem operator trace 1\n# clock: hours\n"),
              HasSubstr("unknown clock 'hours'"));
}

}  // namespace
}  // namespace tandem
