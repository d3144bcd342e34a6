#include "tandem/scene/ply_header.hpp"

#include <fstream>
#include <string>
#include <vector>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"

namespace tandem {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

bool valid_line(const std::vector<std::string_view>& w) {
  const std::string_view key = w.empty() ? std::string_view() : w[0];
  if (key == "comment" || key == "obj_info")
    return true;
  if (key == "format") {
    return w.size() == 3 && w[2] == "1.0" &&
           (w[1] == "ascii" || w[1] == "binary_little_endian" || w[1] == "binary_big_endian");
  }
  if (key == "element")
    return w.size() == 3 && parse_uint(w[2]).has_value();
  if (key == "property")
    return (w.size() == 3 && w[1] != "list") || (w.size() == 5 && w[1] == "list");
  return false;
}

}  // namespace

void check_ply_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  std::size_t bytes = 0;
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
    if (!words.empty() && words[0] == "end_header")
      return;
    if (!valid_line(words)) {
      throw InputError(file.string() + ":" + std::to_string(n),
                       "malformed PLY header line '" + line.substr(0, 80) + "'");
    }
  }
  throw InputError(file.string(), "the PLY header has no 'end_header' line in its first 64 KiB");
}

}  // namespace tandem
