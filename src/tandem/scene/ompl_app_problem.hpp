#pragma once
// OMPL.app problem files (.cfg), read exactly as OMPL.app reads them, so that the sample solutions
// shipped with them (.path) validate in tandem. See ../shared/notes/engineering.md for the
// conventions.

#include <filesystem>

#include "tandem/scene/problem.hpp"

namespace tandem {

/// Throws InputError naming the file (and line) for a missing or malformed file, an unknown key, or
/// a mesh that cannot be loaded.
Problem load_ompl_app_problem(const std::filesystem::path& cfg_file);

}  // namespace tandem
