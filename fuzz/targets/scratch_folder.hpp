#pragma once
// Where the fuzz targets write the files a parser reads: a folder of this process's own under the
// temporary folder, emptied for every input (and removed when the process exits).
//
// Bundles: the targets whose files name other files (a problem and its meshes, a URDF) take one
// input holding several files. The main file is the text before the first line that starts with
// "--- file "; each such line starts a file named by the rest of the line. Names are single path
// components of letters, digits, '.', '-' and '_' (at most 64 bytes, not "." or ".."); a file
// with another name is dropped, as is a second file of the same name.
//
// Threading: one thread (the fuzzing loop) uses the folder.

#include <filesystem>
#include <string_view>

namespace tandem::fuzz {

/// The process's scratch folder, emptied.
std::filesystem::path fresh_scratch_folder();

/// Writes `bytes` to `name` in the scratch folder (which it does not empty); returns the path.
std::filesystem::path write_scratch_file(std::string_view name, std::string_view bytes);

/// Empties the scratch folder, writes the bundle's files into it, the main one as `main_name`;
/// returns the main file's path.
std::filesystem::path write_bundle(std::string_view input, std::string_view main_name);

}  // namespace tandem::fuzz
