// The planner registry: planners by name, and the operator each needs or refuses.

#include "tandem/planning/planner_registry.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "support/problems.hpp"

namespace tandem {
namespace {

using Fixture = test::OperatorFixture;
using ::testing::HasSubstr;

TEST(IRRT, NeedsAnOperator) {
  Fixture f;
  EXPECT_THAT(test::error_message<std::invalid_argument>([&] {
                return make_planner("irrt", f.validator, f.problem.start, f.problem.goal,
                                    PlannerSettings{});
              }),
              HasSubstr("planner 'irrt' needs an operator"));
}

}  // namespace
}  // namespace tandem
