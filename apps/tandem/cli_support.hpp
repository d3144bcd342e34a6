#pragma once
// Helpers shared by the subcommands.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "tandem/collision/motion_validator.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem::cli {

/// Options every command that loads a problem has.
struct ProblemArgs {
  std::string problem;
  std::vector<std::string> allowed_dirs;
  TakeOutOptions take_out;  ///< for a STEP or IGES problem: --part and how to take it out
};

void add_problem_args(CLI::App& command, ProblemArgs& args);
/// The required PATHFILE argument of the commands that read a path.
void add_path_file_arg(CLI::App& command, std::string& path_file);
/// --linear-deflection and --angular-deflection, in the help's `group`.
void add_tessellation_args(CLI::App& command, CadOptions& options, const std::string& group);
/// --part, --margin, --seat-tolerance and the tessellation's deflections.
void add_take_out_args(CLI::App& command, TakeOutOptions& options);
Problem load_problem(const ProblemArgs& args);

/// Throws InputError (naming the problem) if the start or the goal is outside the bounds or
/// collides, naming the obstacle it touches.
/// With a clearance (ValidationSettings::clearance), also if either is closer than it.
void require_valid_endpoints(const Problem& problem, CollisionChecker& checker,
                             const ValidationSettings& validation = {});

}  // namespace tandem::cli
