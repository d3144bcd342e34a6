#include "tandem/io/path_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

const SE3Space& space3() {
  static const SE3Space s(SpaceKind::se3, Bounds{{-10, -10, -10}, {10, 10, 10}});
  return s;
}
const SE3Space& plane() {
  static const SE3Space s(SpaceKind::planar, Bounds{{-10, -10, 0}, {10, 10, 0}});
  return s;
}

TEST(PathFile, RoundTripsExactly) {
  Rng rng(3);
  Path path;
  for (int i = 0; i < 200; ++i)
    path.push_back(space3().sample_uniform(rng));
  const Path back = parse_path(format_path(path, space3()), space3(), "p");
  ASSERT_EQ(back.size(), path.size());
  for (std::size_t i = 0; i < path.size(); ++i)
    ASSERT_TRUE(back[i] == path[i]) << i;
}

TEST(PathFile, WritesOmplsColumns) {
  Config q;
  q.t = {1, 2, 3};
  q.q = Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5);  // w, x, y, z
  EXPECT_EQ(format_path({q}, space3()), "1 2 3 0.5 -0.5 0.5 0.5\n");
  EXPECT_EQ(format_path({plane().planar_config(1, 2, 0.5)}, plane()), "1 2 0.5\n");
}

TEST(PathFile, ReadsPlanarPathsAsYaw) {
  const Path p = parse_path("0.01 -0.15 0.0\n\n# a comment\n1 2 3.0\n", plane(), "maze.path");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(SE3Space::yaw(p[1].q), 3.0, 1e-12);
}

TEST(PathFile, NormalisesQuaternionsOnlyWhenNeeded) {
  const Path p = parse_path("0 0 0 0 0 0 2\n", space3(), "p");
  EXPECT_DOUBLE_EQ(p[0].q.w(), 1.0);
}

// Squaring 1e308 overflows: the quaternion must still come out as the unit one it points along (a
// fuzzing finding: it read as the zero quaternion).
TEST(PathFile, NormalisesHugeQuaternionsWithoutOverflow) {
  const Path p = parse_path("0 0 0 0 1e308 0 1e308\n", space3(), "p");
  EXPECT_NEAR(p[0].q.y(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(p[0].q.w(), std::sqrt(0.5), 1e-15);
}

std::string error_of(const std::string& text, const SE3Space& space) {
  try {
    parse_path(text, space, "bad.path");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted " << text;
  return {};
}

TEST(PathFile, ReportsMalformedLines) {
  EXPECT_THAT(error_of("0 0 0 0 0 0 1\n1 2 3\n", space3()),
              HasSubstr("bad.path:2: expected 7 numbers"));
  EXPECT_THAT(error_of("0 0 0 0 0 0 1\n", plane()),
              HasSubstr("bad.path:1: expected 3 numbers (x y theta)"));
  EXPECT_THAT(error_of("0 0 zero 0 0 0 1\n", space3()), HasSubstr("'zero' is not a finite number"));
  EXPECT_THAT(error_of("0 0 inf 0 0 0 1\n", space3()), HasSubstr("'inf' is not a finite number"));
  EXPECT_THAT(error_of("0 0 0 0 0 0 0\n", space3()), HasSubstr("the quaternion is zero"));
  EXPECT_THAT(error_of("\n\n", space3()), HasSubstr("bad.path: the path has no states"));
}

TEST(PathFile, ReportsMissingFiles) {
  test::TempDir dir;
  EXPECT_THAT(test::error_message<InputError>(
                  [&] { return read_path_file(dir.path() / "none.path", space3()); }),
              HasSubstr("none.path: no such file"));
  EXPECT_THAT(test::error_message<InputError>([&] {
                write_path_file(dir.path() / "no" / "such" / "folder.path", {Config{}}, space3());
              }),
              HasSubstr("folder.path: cannot be written"));
}

}  // namespace
}  // namespace tandem
