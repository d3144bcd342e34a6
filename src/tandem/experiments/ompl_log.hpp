#pragma once
// OMPL's benchmark log format (ompl::tools::Benchmark::saveResultsToStream; grammar in OMPL's
// doc/markdown/benchmark.md), so that `ompl_benchmark_statistics` turns an experiment into the
// SQLite database Planner Arena reads. Each configuration of the experiment is one "planner";
// its parameters are the planner's common properties. Run properties use OMPL's names where OMPL
// has one (time, solved, status, graph states, ...) and tandem's own otherwise (nodes operator,
// contact entries, ...); the status is OMPL's PlannerStatus enum.

#include <string>
#include <vector>

#include "tandem/experiments/bench_runner.hpp"
#include "tandem/experiments/experiment.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

struct OmplLogHeader {
  std::string version;  ///< tandem's version
  std::string hostname;
  std::string date;     ///< when the experiment was (last) run
  std::string cpuinfo;  ///< may be empty
  double total_time_s = 0.0;
};

/// The log of the records (grouped by configuration, in the experiment's order).
std::string format_ompl_log(const Experiment& experiment, const Problem& problem,
                            const std::vector<RunRecord>& records, const OmplLogHeader& header);

/// OMPL's PlannerStatus name for a tandem status ("Exact solution", "Timeout", ...).
std::string ompl_status_name(const std::string& tandem_status);

}  // namespace tandem
