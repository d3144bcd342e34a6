#include "scratch_folder.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <system_error>

namespace tandem::fuzz {
namespace {

constexpr std::string_view kFileMarker = "--- file ";
constexpr std::size_t kMaxNameBytes = 64;

const std::filesystem::path& scratch_root() {
  static const std::filesystem::path root = [] {
    std::filesystem::path p =
        std::filesystem::temp_directory_path() / ("tandem-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(scratch_root(), ignored);
    });
    return p;
  }();
  return root;
}

bool usable_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxNameBytes || name == "." || name == "..")
    return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
           c == '-' || c == '_';
  });
}

/// The offset of the next line starting with the marker at or after `from`, or npos.
std::size_t next_marker(std::string_view input, std::size_t from) {
  for (std::size_t at = from; at < input.size();) {
    if (input.substr(at, kFileMarker.size()) == kFileMarker)
      return at;
    const std::size_t eol = input.find('\n', at);
    if (eol == std::string_view::npos)
      return std::string_view::npos;
    at = eol + 1;
  }
  return std::string_view::npos;
}

}  // namespace

std::filesystem::path fresh_scratch_folder() {
  const std::filesystem::path& root = scratch_root();
  for (const auto& entry : std::filesystem::directory_iterator(root))
    std::filesystem::remove_all(entry.path());
  return root;
}

std::filesystem::path write_scratch_file(std::string_view name, std::string_view bytes) {
  const std::filesystem::path file = scratch_root() / name;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return file;
}

std::filesystem::path write_bundle(std::string_view input, std::string_view main_name) {
  fresh_scratch_folder();
  std::size_t marker = next_marker(input, 0);
  const std::filesystem::path main = write_scratch_file(main_name, input.substr(0, marker));
  std::set<std::string, std::less<>> written{std::string(main_name)};
  while (marker != std::string_view::npos) {
    const std::size_t name_end = std::min(input.find('\n', marker), input.size());
    const std::string_view name =
        input.substr(marker + kFileMarker.size(), name_end - marker - kFileMarker.size());
    const std::size_t start = std::min(name_end + 1, input.size());
    marker = next_marker(input, start);
    const std::size_t end = marker == std::string_view::npos ? input.size() : marker;
    if (usable_name(name) && written.insert(std::string(name)).second)
      write_scratch_file(name, input.substr(start, end - start));
  }
  return main;
}

}  // namespace tandem::fuzz
