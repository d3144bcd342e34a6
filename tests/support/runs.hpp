#pragma once
// Runs that tests of several stages share: a planner on a real problem, a live session's spec, and
// an experiment on the wall with a gap.

#include <cstdint>
#include <string>

#include "support/test_support.hpp"
#include "tandem/experiments/experiment.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/runs/run_spec.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem::test {

struct PlanRun {
  PlannerStatus status;
  PlannerStats stats;
  bool path_valid = false;
};

/// Runs the named planner (the problem's range hint for it, if any) with a time limit, and checks
/// its path with a fresh checker.
PlanRun plan(const Problem& problem, const std::string& planner_name, std::uint64_t seed,
             double time_limit);

/// A live session's spec: interactive-contact, last-valid extension, alpha 0.3, the experienced
/// operator, 20 s.
RunSpec live_spec(std::uint64_t seed);

/// The wall-with-gap problem with a guide through the gap, and an experiment of two
/// configurations x 3 seeds on it.
struct ExperimentFixture {
  Problem problem = wall_with_gap_problem();
  Experiment experiment;
  ExperimentFixture();
};

}  // namespace tandem::test
