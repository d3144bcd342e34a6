#pragma once
// OMPL's path format: one state per line; "x y z qx qy qz qw" in SE(3), "x y theta" in planar
// spaces. This is what OMPL's PathGeometric::printAsMatrix writes and OMPL.app loads.

#include <filesystem>
#include <string>

#include "tandem/planning/path.hpp"

namespace tandem {

/// Writes with 17 significant digits, so reading the file gives back the same numbers.
std::string format_path(const Path& path, const SE3Space& space);
void write_path_file(const std::filesystem::path& file, const Path& path, const SE3Space& space);

/// Blank lines and lines starting with '#' are skipped. Throws InputError naming `source` and the
/// line for a wrong number of values, a malformed or non-finite number, or a zero quaternion.
/// Quaternions whose norm is off 1 by more than 1e-12 are normalised (those within keep their exact
/// bits).
Path parse_path(const std::string& text, const SE3Space& space, const std::string& source);
Path read_path_file(const std::filesystem::path& file, const SE3Space& space);

}  // namespace tandem
