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
};

void add_problem_args(CLI::App& command, ProblemArgs& args);
Problem load_problem(const ProblemArgs& args);

/// Throws InputError (naming the problem) if the start or the goal is outside the bounds or
/// collides, naming the obstacle it touches.
void require_valid_endpoints(const Problem& problem, CollisionChecker& checker);

}  // namespace tandem::cli
