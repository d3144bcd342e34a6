#pragma once
// One run of one planner on one problem, as the benchmark records it.

#include <cstddef>
#include <cstdint>
#include <string>

namespace bench {

struct RunResult {
  std::string planner;       ///< "tandem-birrt+rrt", "ompl-rrtconnect", "ompl-kpiece1", ...
  unsigned threads = 1;      ///< the threads the planner was given
  unsigned member = 0;       ///< tandem only: the portfolio member whose search won
  double range = 0.0;        ///< the planner's range after its setup
  bool solved = false;       ///< an exact solution
  double time_s = 0.0;       ///< wall time of the solve call
  std::uint64_t checks = 0;  ///< state validity checks (OMPL's checker, or tandem's validator)
  std::size_t nodes = 0;     ///< vertices of the planner's trees
  double path_length = 0.0;  ///< of the solution as the planner returned it (not simplified)
  /// tandem only, with --profile: time in collision and nearest-neighbour queries.
  double collision_time_s = 0.0;
  double nearest_time_s = 0.0;
};

}  // namespace bench
