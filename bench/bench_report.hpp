#pragma once
// The benchmark's report: a table per problem (one row per planner), the ratios of tandem's median
// time to OMPL RRTConnect's and to the best OMPL planner's, and the same as a Markdown table (one
// row per problem).

#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "run_result.hpp"

namespace bench {

/// One planner's runs on one problem. Unsolved runs count at the time limit.
struct PlannerSummary {
  std::string planner;
  unsigned threads = 1;
  double range = 0.0;
  int runs = 0;
  int solved = 0;
  double median_s = 0.0;
  double p90_s = 0.0;  ///< by nearest rank
  double median_checks = 0.0;
  double median_nodes = 0.0;
};

PlannerSummary summarize(const std::vector<RunResult>& runs, double time_limit);

/// tandem's solutions re-checked: by OMPL's PathGeometric::check() and by tandem's check_path.
struct PathChecks {
  int checked = 0;
  int ompl_failures = 0;
  int tandem_failures = 0;
};

struct ProblemReport {
  std::string problem;
  double time_limit = 0.0;
  int runs = 0;
  PlannerSummary tandem;
  std::vector<PlannerSummary> ompl;  ///< in --planners order
  PathChecks paths;

  /// OMPL's RRTConnect, if it ran.
  const PlannerSummary* rrtconnect() const;
  /// The OMPL planner that solved most, then has the lowest median; nullptr if none ran.
  const PlannerSummary* best_ompl() const;
};

void print_report(std::FILE* out, const ProblemReport& report);

void write_markdown_header(std::ostream& out);
void write_markdown_row(std::ostream& out, const ProblemReport& report);

}  // namespace bench
