// The state the viewer streams: each browser gets every node once, and starts over after a reset.

#include "tandem/web/viewer_state.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>

#include "support/test_support.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

TEST(ViewerState, EachBrowserGetsEveryNodeOnceAndStartsOverAfterAReset) {
  const Problem problem = test::wall_with_gap_problem();
  ViewerState state(problem, "birrt", false);
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  PlannerSettings settings;
  settings.seed = 3;
  auto planner = make_planner("birrt", validator, problem.start, problem.goal, settings);
  for (int k = 0; k < 20; ++k)
    planner->step();
  state.update(*planner, "{\"type\":\"status\"}", "");
  ViewerState::Cursor early, late;
  auto nodes_in = [](const std::vector<Frame>& frames) {
    std::size_t n = 0;
    for (const Frame& f : frames) {
      if (f.binary) {
        std::uint32_t count;
        std::memcpy(&count, f.data.data() + 12, 4);
        n += count;
      }
    }
    return n;
  };
  std::vector<Frame> first = state.pending(early);
  ASSERT_FALSE(first.empty());
  EXPECT_THAT(first.front().data, HasSubstr("\"hello\""));
  EXPECT_EQ(nodes_in(first), planner->stats().nodes);
  EXPECT_TRUE(state.pending(early).empty()) << "nothing new, nothing sent";
  for (int k = 0; k < 20; ++k)
    planner->step();
  state.update(*planner, "{\"type\":\"status\",\"n\":2}", "");
  const std::size_t before = nodes_in(first);
  EXPECT_EQ(nodes_in(state.pending(early)), planner->stats().nodes - before) << "deltas only";
  EXPECT_EQ(nodes_in(state.pending(late, 5)), 5u) << "a batch is bounded";
  EXPECT_EQ(nodes_in(state.pending(late)), planner->stats().nodes - 5) << "the rest follows";
  state.restarted();
  const std::vector<Frame> after = state.pending(early);
  ASSERT_FALSE(after.empty());
  EXPECT_THAT(after.front().data, HasSubstr("\"reset\""));
  EXPECT_EQ(nodes_in(after), 0u);
}

}  // namespace
}  // namespace tandem
