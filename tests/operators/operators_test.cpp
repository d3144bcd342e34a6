// Simulated operators and traces.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"
#include "tandem/operators/guide_follower.hpp"
#include "tandem/operators/trace.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

const SE3Space& space() {
  static const SE3Space s(SpaceKind::se3, Bounds{{-5, -5, 0}, {5, 5, 2}});
  return s;
}

std::vector<Config> guide() {
  std::vector<Config> k(3);
  k[0].t = {-4, 0, 1};
  k[1].t = {0, 3, 1};
  k[1].q = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
  k[2].t = {4, 0, 1};
  return k;
}

TEST(GuideFollower, WalksTheGuideFromStartToEnd) {
  const auto profile = operator_profile("experienced", space(), OperatorClock::ticks);
  const GuideFollower op(space(), guide(), profile, 1);
  EXPECT_NEAR(op.end_time(), op.guide_length() / profile.speed, 1e-6);  // no pauses
  EXPECT_LT((op.read(0).q_device.t - guide()[0].t).norm(), 3 * profile.tremor_translation);
  EXPECT_LT((op.read(op.end_time() + 100).q_device.t - guide()[2].t).norm(),
            3 * profile.tremor_translation);
  // Halfway in time is halfway along the guide.
  EXPECT_NEAR(op.progress(op.end_time() / 2), op.guide_length() / 2, 1e-9);
  // Its velocity follows the guide.
  const DeviceReading r = op.read(op.end_time() / 4);
  EXPECT_GT(r.velocity.head<3>().norm(), 0.5 * profile.speed);
}

TEST(GuideFollower, IsAPureFunctionOfTime) {
  const auto profile = operator_profile("inexperienced", space(), OperatorClock::ticks);
  const GuideFollower a(space(), guide(), profile, 7), b(space(), guide(), profile, 7);
  for (double t : {5000.0, 10.0, 123456.0, 10.0, 77.5}) {
    EXPECT_TRUE(a.read(t).q_device == b.read(t).q_device);
    EXPECT_TRUE(a.read(t).q_device == a.read(t).q_device);
  }
  const GuideFollower c(space(), guide(), profile, 8);
  EXPECT_FALSE(a.read(5000).q_device == c.read(5000).q_device);
}

TEST(GuideFollower, InexperiencedOperatorsAreSlowNoisyAndHesitate) {
  const auto fast = operator_profile("experienced", space(), OperatorClock::ticks);
  const auto slow = operator_profile("inexperienced", space(), OperatorClock::ticks);
  EXPECT_LT(slow.speed, fast.speed);
  EXPECT_GT(slow.tremor_translation, fast.tremor_translation);
  const GuideFollower op(space(), guide(), slow, 3);
  EXPECT_GT(op.end_time(), op.guide_length() / slow.speed);  // pauses and back-ups take time
  int pauses = 0, backups = 0;
  double previous = op.progress(0);
  const double dt = 10.0;
  for (double t = dt; t < op.end_time(); t += dt) {
    const double s = op.progress(t);
    pauses += s == previous;
    backups += s < previous;
    previous = s;
  }
  EXPECT_GT(pauses, 0);
  EXPECT_GT(backups, 0);
  // Tremor: off the guide, but within a few amplitudes.
  double off = 0.0;
  for (double t = 0; t < op.end_time(); t += 97.0) {
    off = std::max(off, (op.read(t).q_device.t - op.guide_pose(op.progress(t)).t).norm());
  }
  EXPECT_GT(off, 0.2 * slow.tremor_translation);
  EXPECT_LT(off, 2.0 * std::sqrt(3.0) * slow.tremor_translation);
}

TEST(GuideFollower, StaysInTheBounds) {
  std::vector<Config> k = guide();
  k[1].t = {0, 4.99, 1.99};
  const GuideFollower op(space(), k,
                         operator_profile("inexperienced", space(), OperatorClock::ticks), 2);
  for (double t = 0; t < op.end_time(); t += 50.0)
    ASSERT_TRUE(space().satisfies_bounds(op.read(t).q_device));
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
