#pragma once
// A PLY file's header, checked before assimp reads the file: assimp 5.2 (Debian 12) loops forever on
// some malformed headers (an "element" line without its count, found by fuzz/targets' cfg target),
// so tandem refuses a header that is not made of PLY's header lines.

#include <filesystem>

namespace tandem {

/// Throws InputError naming the file and the line unless the file starts with "ply", its header
/// lines are "format ascii|binary_little_endian|binary_big_endian 1.0", "comment …", "obj_info …",
/// "element NAME COUNT" (COUNT a whole number), "property TYPE NAME" or "property list TYPE TYPE
/// NAME", and "end_header" ends it within the first 64 KiB; and unless the file holds at least a
/// byte per declared element entry after the header (assimp allocates what the counts declare).
void check_ply_header(const std::filesystem::path& file);

}  // namespace tandem
