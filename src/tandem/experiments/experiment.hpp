#pragma once
// Experiment files: sweeps of planner runs, as the papers' tables and figures report them.
//
//   name = "env1-alpha-contact"
//   description = "..."
//   problem = "cluttered-1"          # a built-in scene, or a problem file relative to this file
//   seeds = 20                       # seeds seed_start .. seed_start + seeds - 1
//   time_limit = 60.0                # seconds per run
//   clock = "wall"                   # optional: "virtual" (default) or "wall" (human time)
//
//   [base]                           # settings of every run (see RunConfig for the keys)
//   mode = "interactive-contact"
//   operator = "experienced"
//
//   [[sweep]]                        # each sweep is the product of its lists, on top of [base];
//   alpha = [0.8, 0.5, 0.2]          # the experiment's runs are the union of its sweeps
//   [[sweep]]
//   mode = ["birrt"]
//
//   [report]
//   title = "Table II: influence of alpha with contact"
//   rows = "alpha"                   # the parameter the tables and plots run along
//   columns = ["mode"]               # parameters that make separate series (optional)
//   panels = "sigma"                 # a parameter that makes separate tables and plots (optional)
//   paper = { "0.8" = "40 s, 1729 nodes" }   # optional: the paper's figures, quoted beside ours
//
// The clock: in virtual time (the default) the simulated operator moves one step per planner
// iteration, deterministically, and runs go --jobs at a time on one thread each. In human time
// ("wall") the operator is a simulated person with human limits on its own thread, the planner on
// another, as in a live session (runs/wall_run.hpp): one run at a time on both cores, and a
// planner that plans alone gets both cores too (threads = 2 unless the experiment sets it).
//
// The keys of [base] and [[sweep]] are "mode" (a planner of the registry) and the tunables the
// tables declare (run_tunables()), with the same ranges as everywhere. Unknown keys, wrong types
// and values out of range are errors naming the file and line.

#include <filesystem>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "tandem/runs/run.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

/// The parameters of one configuration, by name, in a fixed order (std::map), and what they set.
struct RunConfig {
  std::map<std::string, ParamValue> values;

  /// "mode=interactive-contact alpha=0.08 ..." (the parameters in name order).
  std::string label() const;
  /// The spec of a run of this configuration with a seed (the operator's seed is the same seed).
  /// What the configuration leaves unset comes from the problem's planner hints (range, extend,
  /// goal bias), then from tandem's defaults, as for `tandem plan`.
  RunSpec spec(std::uint64_t seed, double time_limit, const ProblemPlannerHints& hints = {}) const;
  /// The value of a parameter as text, or "" if the configuration does not set it.
  std::string value_text(const std::string& name) const;
};

/// Whether an experiment may set `name`: "mode" or a tunable of run_tunables().
bool is_run_parameter(std::string_view name);

struct ReportSpec {
  std::string title;
  std::string rows;                  ///< parameter along the table's rows and the plots' x axis
  std::vector<std::string> columns;  ///< parameters whose values make separate series
  std::string panels;                ///< parameter whose values make separate tables and plots
  std::map<std::string, std::string> paper;  ///< row value -> the paper's figures, quoted
};

struct Experiment {
  std::string name;
  std::string description;
  std::string problem;             ///< as given
  std::filesystem::path base_dir;  ///< the experiment file's folder
  std::uint64_t seeds = 20;
  std::uint64_t seed_start = 1;
  double time_limit = 60.0;
  std::string clock = "virtual";   ///< "virtual" or "wall" (human time)
  std::vector<RunConfig> configs;  ///< distinct, in the order the sweeps list them
  ReportSpec report;
};

/// Throws InputError naming the file and line.
Experiment load_experiment(const std::filesystem::path& file);
Experiment parse_experiment(const std::string& text, const std::string& source,
                            const std::filesystem::path& base_dir);

}  // namespace tandem
