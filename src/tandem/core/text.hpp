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

/// Writes `text` to a temporary file beside `file`, then renames it over `file`: a crash never
/// leaves a half-written file. Throws InputError naming the file.
void write_file_atomically(const std::filesystem::path& file, const std::string& text);

/// Splits on runs of whitespace.
std::vector<std::string_view> split_whitespace(std::string_view s);

}  // namespace tandem
