#pragma once
// Strict parsing of numbers and small text helpers shared by the file readers.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tandem {

std::string trim(std::string_view s);

/// The whole of `s` (after trimming) as a double, or nothing ("1.5x", "", "nan" are rejected only
/// for the syntax; callers check finiteness).
std::optional<double> parse_double(std::string_view s);

/// The whole of `s` as an unsigned 64-bit integer, or nothing (no sign, no spaces, no overflow).
std::optional<std::uint64_t> parse_uint(std::string_view s);

/// The whole file. Throws InputError naming the file if it is missing, not a regular file, or
/// unreadable.
std::string read_text_file(const std::filesystem::path& file);

/// The first and the last `bytes` bytes of a file (the whole file in both when it is shorter):
/// to check how a large file begins and ends without reading it all. Throws InputError as
/// read_text_file does.
struct FileEnds {
  std::string head, tail;
};
FileEnds read_file_ends(const std::filesystem::path& file, std::size_t bytes);

/// Throws InputError when a file name holds a NUL byte. The file system sees the name only up to
/// it, so what tandem checks of the whole name (its extension: which reader, which checks) would
/// not hold for the file opened (fuzzing: "a.ply\0.dae" was checked as COLLADA and read by
/// assimp's PLY reader, which hung). `source` names where the name was given; empty, the error
/// names the file alone.
void check_file_name(const std::string& name, const std::string& source = {});

/// The file name's extension, with its dot, in lower case ("part.STL" -> ".stl").
std::string lower_extension(const std::filesystem::path& file);

/// Writes `text` to a temporary file beside `file`, then renames it over `file`: a crash never
/// leaves a half-written file. Throws InputError naming the file.
void write_file_atomically(const std::filesystem::path& file, const std::string& text);

/// Splits on runs of whitespace.
std::vector<std::string_view> split_whitespace(std::string_view s);

}  // namespace tandem
