// The SpaceMouse through spacenavd.

#include "tandem/operators/spacenav.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace tandem {
namespace {

using ::testing::HasSubstr;

TEST(SpaceNav, SaysWhyWhenTheDaemonIsAbsent) {
  std::string why;
  const std::unique_ptr<SpaceNav> nav = SpaceNav::open(&why);
  if (nav != nullptr)
    GTEST_SKIP() << "spacenavd is running here (" << nav->name() << ")";
  EXPECT_THAT(why, HasSubstr("spacenavd is not running"));
  EXPECT_THAT(why, HasSubstr("browser"));
}

}  // namespace
}  // namespace tandem
