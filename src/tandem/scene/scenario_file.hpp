#pragma once
// tandem's own scenario files: human-editable TOML describing a whole problem (see
// docs/scenario-format.md).

#include <filesystem>
#include <string>
#include <string_view>

#include "tandem/scene/file_refs.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

/// Throws InputError naming the file and line for a missing or malformed file, an unknown or
/// missing key, a value of the wrong type or out of range, a duplicate obstacle name, or a
/// referenced file that cannot be used.
Problem load_scenario_file(const std::filesystem::path& file, const FileAccess& access);

/// Parses scenario text; `source` names it in messages and `base` is the file relative names are
/// resolved against (for a built-in scene, a name that is no file: such scenes must not refer to
/// files).
Problem parse_scenario(std::string_view text, const std::string& source,
                       const std::filesystem::path& base, const FileAccess& access);

}  // namespace tandem
