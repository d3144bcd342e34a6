#pragma once
// One entry point for every kind of problem the user can name: an OMPL.app .cfg, a tandem scenario
// (.toml), or the name of a built-in scene.

#include <filesystem>
#include <string>
#include <vector>

#include "tandem/scene/problem.hpp"
#include "tandem/scene/take_out.hpp"

namespace tandem {

struct ProblemLoadOptions {
  /// Folders referenced files may come from, besides the problem file's own folder.
  std::vector<std::filesystem::path> allowed_dirs;
  /// For a STEP or IGES file: the part to take out, and how (take_out.hpp).
  TakeOutOptions take_out;
};

/// Throws InputError naming the file (or the name) and the fault.
Problem load_problem(const std::string& spec, const ProblemLoadOptions& options = {});

}  // namespace tandem
