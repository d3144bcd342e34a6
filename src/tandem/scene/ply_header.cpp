#include "tandem/scene/ply_header.hpp"

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"

namespace tandem {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

/// An element's name: a letter or '_' first, then letters, digits, '_' or '-'. assimp 5.2 read
/// "element 88888888888888888888888888888vertex 4" as a count of billions and allocated 22 GB
/// (found by fuzz/targets' cfg target).
bool is_name(std::string_view name) {
  const auto letter = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  };
  if (name.empty() || !letter(name[0]))
    return false;
  for (const char c : name) {
    if (!letter(c) && !(c >= '0' && c <= '9') && c != '-')
      return false;
  }
  return true;
}

bool valid_line(const std::vector<std::string_view>& w) {
  const std::string_view key = w.empty() ? std::string_view() : w[0];
  if (key == "comment" || key == "obj_info")
    return true;
  if (key == "format") {
    return w.size() == 3 && w[2] == "1.0" &&
           (w[1] == "ascii" || w[1] == "binary_little_endian" || w[1] == "binary_big_endian");
  }
  if (key == "element")
    return w.size() == 3 && is_name(w[1]) && parse_uint(w[2]).has_value();
  if (key == "property")
    return (w.size() == 3 && w[1] != "list") || (w.size() == 5 && w[1] == "list");
  return false;
}

/// A declared element.
struct Element {
  int line = 0;
  std::string name;
  std::uint64_t count = 0;
};

/// Throws InputError unless the file holds at least one byte per declared entry after its header:
/// assimp 5.2 allocates what the counts declare before it reads (25 GB for "element face
/// 8888888888888888885", found by fuzz/targets' cfg target).
void check_counts(const std::filesystem::path& file, const std::vector<Element>& elements,
                  std::size_t header_bytes) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  std::uint64_t left = !error && size > header_bytes ? size - header_bytes : 0;
  for (const Element& e : elements) {
    if (e.count > left) {
      throw InputError(file.string() + ":" + std::to_string(e.line),
                       "element '" + e.name + "' declares " + std::to_string(e.count) +
                           " entries, more than the file holds after its header");
    }
    left -= e.count;
  }
}

}  // namespace

void check_ply_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  std::size_t bytes = 0;
  std::vector<Element> elements;
  for (int n = 1; std::getline(in, line) && bytes < kMaxHeaderBytes; ++n) {
    bytes += line.size() + 1;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    const auto words = split_whitespace(line);
    if (n == 1) {
      if (line != "ply")
        throw InputError(file.string(), "not a PLY file (the first line must be 'ply')");
      continue;
    }
    if (!words.empty() && words[0] == "end_header") {
      check_counts(file, elements, bytes);
      return;
    }
    if (!valid_line(words)) {
      throw InputError(file.string() + ":" + std::to_string(n),
                       "malformed PLY header line '" + line.substr(0, 80) + "'");
    }
    if (words[0] == "element")
      elements.push_back({n, std::string(words[1]), *parse_uint(words[2])});
  }
  throw InputError(file.string(), "the PLY header has no 'end_header' line in its first 64 KiB");
}

}  // namespace tandem
