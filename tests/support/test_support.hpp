#pragma once
// Shared helpers for tandem's tests: scenes made of boxes, temporary folders, running the program.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tandem/scene/problem.hpp"

namespace tandem::test {

/// A configuration at (x, y, z), turned by `yaw` about z.
Config at(double x, double y, double z = 0.0, double yaw = 0.0);

/// The message of the `E` that `f()` throws, for EXPECT_THAT(..., HasSubstr(...)). Another
/// exception propagates (and fails the test); if nothing is thrown, a failure is added and the
/// result is "(nothing was thrown)".
template <class E, class F>
std::string error_message(F&& f) {
  try {
    (void)std::forward<F>(f)();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an exception, nothing was thrown";
  return "(nothing was thrown)";
}

/// An axis-aligned box obstacle.
Body box_body(const std::string& name, const Eigen::Vector3d& size,
              const Eigen::Vector3d& position);

/// A 1 x 0.2 x 0.2 bar object and a wall at x in [-0.05, 0.05] across the whole bounds [-3, 3]^2 x
/// [-1, 1] but for a gap of 0.6 around y = 0; start at x = -2, goal at x = 2.
Problem wall_with_gap_problem();

/// A fresh folder under the system's temporary folder, removed at destruction.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const;

 private:
  std::filesystem::path path_;
};

/// The shared folder (../shared) if present; tests that need it GTEST_SKIP() otherwise.
std::filesystem::path shared_dir();
bool have_shared_data();
/// The problems tandem ships (the built-in scenes), then the OMPL.app problems of ../shared (3D,
/// then 2D) when it is present.
std::vector<std::string> shipped_problems();
/// Configurations at the boundary of collision, where conservative shortcuts are most likely to be
/// wrong: for pairs of uniform samples, one free and one colliding, the straight motion between
/// them bisected 40 times; both ends of the last bisection (one free, one colliding, a hair apart)
/// are returned. `pairs` such pairs at most (fewer if the problem has no free or no colliding
/// samples in 200 x pairs tries).
std::vector<Config> near_contact_configs(const Problem& problem, std::uint64_t seed,
                                         std::size_t pairs);
#define TANDEM_REQUIRE_SHARED_DATA()                                                             \
  do {                                                                                           \
    if (!::tandem::test::have_shared_data())                                                     \
      GTEST_SKIP() << "../shared/benchmarks/omplapp is absent: OMPL.app problems not available"; \
  } while (0)

std::filesystem::path source_dir();

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs the tandem program with the arguments (no shell), capturing stdout and stderr.
RunResult run_tandem(const std::vector<std::string>& args);

}  // namespace tandem::test
