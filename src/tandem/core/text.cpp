#include "tandem/core/text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <iterator>

#include "tandem/core/error.hpp"

namespace tandem {

std::string trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b])))
    ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1])))
    --e;
  return std::string(s.substr(b, e - b));
}

std::optional<double> parse_double(std::string_view s) {
  const std::string t = trim(s);
  if (t.empty())
    return std::nullopt;
  double v = 0.0;
  const char* first = t.data();
  if (*first == '+')
    ++first;  // from_chars rejects a leading '+', which people write
  auto [ptr, ec] = std::from_chars(first, t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size())
    return std::nullopt;
  return v;
}

std::optional<std::uint64_t> parse_uint(std::string_view s) {
  const std::string t = trim(s);
  if (t.empty())
    return std::nullopt;
  std::uint64_t v = 0;
  auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || ptr != t.data() + t.size())
    return std::nullopt;
  return v;
}

namespace {

/// The file opened for reading; InputError naming it if it is missing, not a regular file, or
/// cannot be opened.
std::ifstream open_for_reading(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw InputError(name, "no such file");
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError(name, "not a regular file");
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw InputError(name, "cannot be opened for reading");
  return in;
}

}  // namespace

std::string read_text_file(const std::filesystem::path& file) {
  std::ifstream in = open_for_reading(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
    throw InputError(file.string(), "read error");
  return text;
}

FileEnds read_file_ends(const std::filesystem::path& file, std::size_t bytes) {
  std::ifstream in = open_for_reading(file);
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::size_t>(in.tellg());
  const std::size_t n = std::min(size, bytes);
  FileEnds ends{std::string(n, '\0'), std::string(n, '\0')};
  in.seekg(0);
  in.read(ends.head.data(), static_cast<std::streamsize>(n));
  in.seekg(static_cast<std::streamoff>(size - n));
  in.read(ends.tail.data(), static_cast<std::streamsize>(n));
  if (!in)
    throw InputError(file.string(), "read error");
  return ends;
}

void check_file_name(const std::string& name, const std::string& source) {
  const std::size_t nul = name.find('\0');
  if (nul == std::string::npos)
    return;
  throw InputError(source, "the file name '" + name.substr(0, nul) + "\\0...' holds a NUL byte");
}

std::string lower_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void write_file_atomically(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc | std::ios::binary);
    if (!out)
      throw InputError(file.string(), "cannot be written");
    out << text;
    out.flush();
    if (!out)
      throw InputError(file.string(), "write error");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError(file.string(), "cannot be written");
  }
}

std::vector<std::string_view> split_whitespace(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i])))
      ++i;
    const std::size_t b = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i])))
      ++i;
    if (i > b)
      out.push_back(s.substr(b, i - b));
  }
  return out;
}

}  // namespace tandem
