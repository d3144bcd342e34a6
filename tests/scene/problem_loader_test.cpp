// Problems by name: a scenario file, an OMPL.app configuration or a built-in scene.

#include "tandem/scene/problem_loader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

TEST(ProblemLoader, NamesTheBuiltinScenesWhenNothingMatches) {
  try {
    load_problem("no-such-scene");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(
                              "no-such-scene: no such file, and no built-in scene of that name"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("cluttered-1"));
  }
}

// A name read only up to its NUL byte: "x.cfg\0.toml" would be read as a scenario from x.cfg.
TEST(ProblemLoader, RefusesANameWithANulByte) {
  EXPECT_THAT(
      test::error_message<InputError>([] { load_problem(std::string("x.cfg") + '\0' + ".toml"); }),
      ::testing::HasSubstr("the file name 'x.cfg\\0...' holds a NUL byte"));
}

}  // namespace
}  // namespace tandem
