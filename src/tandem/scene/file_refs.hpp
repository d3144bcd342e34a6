#pragma once
// Resolving file names that one file gives for another (a mesh named in a scenario or a URDF).
//
// Relative names are resolved against the referring file's folder. The result must lie under one of
// the allowed roots (by default the folder of the problem file the user named), so a problem file
// cannot make tandem read arbitrary files; URIs other than file:// (package://, http://) are
// refused.

#include <filesystem>
#include <string>
#include <vector>

namespace tandem {

struct FileAccess {
  /// Folders files may be read from; empty means no restriction.
  std::vector<std::filesystem::path> roots;
};

/// Throws InputError naming `referrer` for a refused URI or a path outside the roots.
std::filesystem::path resolve_reference(const std::string& reference,
                                        const std::filesystem::path& referrer,
                                        const FileAccess& access);

}  // namespace tandem
