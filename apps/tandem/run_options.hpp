#pragma once
// The options of a planning run, shared by `tandem plan` and `tandem interactive`: the problem,
// the planner mode and its settings, and the human loop's operator and tunables.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "cli_support.hpp"
#include "tandem/experiments/run.hpp"

namespace tandem::cli {

struct RunArgs {
  ProblemArgs problem;
  std::optional<std::string> planner;
  std::optional<std::string> mode;
  std::optional<std::uint64_t> seed;
  std::optional<double> time_limit;
  std::optional<double> range;
  std::optional<double> goal_bias;
  std::optional<std::string> extend;
  // The human loop.
  std::string operator_name = "experienced";
  double operator_speed = 1.0;
  std::optional<std::uint64_t> operator_seed;
  std::uint64_t operator_period = 10;
  std::optional<double> alpha;
  int contact_samples = 10;
  double contact_distance = 0.0;
  std::string sampling = "mag";
  double sigma = 0.0;
  double force_mix = 0.5;
  int neighbours = 10;
  int uniform_every = 10;
};

void add_run_options(CLI::App& app, RunArgs& args);
/// The run the options describe for this problem (the problem's own settings fill the gaps).
RunSpec make_spec(const RunArgs& args, const Problem& problem);

}  // namespace tandem::cli
