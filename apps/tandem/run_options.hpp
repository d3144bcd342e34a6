#pragma once
// The options of a planning run, shared by `tandem plan` and `tandem interactive`: the problem,
// the planner and every tunable the tables declare (one option each, --name-with-dashes), and the
// seeds and time limit.

#include <CLI/CLI.hpp>
#include <map>
#include <optional>
#include <string>

#include "cli_support.hpp"
#include "tandem/runs/run_spec.hpp"

namespace tandem::cli {

struct RunArgs {
  ProblemArgs problem;
  std::optional<std::string> planner;
  std::optional<std::string> mode;
  std::optional<std::uint64_t> seed;
  std::optional<std::uint64_t> operator_seed;
  std::optional<double> time_limit;
  /// The tunables given on the command line, by name, as typed (checked by make_spec).
  std::map<std::string, std::string> tunables;
};

void add_run_options(CLI::App& app, RunArgs& args);
/// The run the options describe for this problem (the problem's own settings fill the gaps).
/// Throws InputError naming the option for a value outside its declared range or a tunable the
/// planner does not use.
RunSpec make_spec(const RunArgs& args, const Problem& problem);

}  // namespace tandem::cli
