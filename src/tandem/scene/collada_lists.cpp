#include "tandem/scene/collada_lists.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>

#include "tandem/core/error.hpp"

namespace tandem {
namespace {

bool integer_list_char(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == ' ' || c == '\t' || c == '\n' ||
         c == '\r';
}

/// Calls visit(open_tag, body) for every <tag ...> element: open_tag is the text between '<' and
/// '>', body the text up to the closing tag (empty for <tag/>).
template <class Visit>
void each_element(const std::string& text, const std::string& tag, const std::string& name,
                  Visit visit) {
  const std::string close = "</" + tag + ">";
  for (std::size_t at = text.find("<" + tag); at != std::string::npos;
       at = text.find("<" + tag, at + 1)) {
    const std::size_t after = at + 1 + tag.size();
    if (after >= text.size() || (text[after] != '>' && text[after] != ' '))
      continue;  // another element whose name starts the same way
    const std::size_t open_end = text.find('>', after);
    if (open_end == std::string::npos)
      throw InputError(name, "malformed COLLADA file: a <" + tag + "> tag is not closed");
    const std::string open = text.substr(at + 1, open_end - at - 1);
    if (text[open_end - 1] == '/') {
      visit(open, std::string_view{});
      continue;
    }
    const std::size_t end = text.find(close, open_end);
    if (end == std::string::npos)
      throw InputError(name, "malformed COLLADA file: a <" + tag + "> element is not closed");
    visit(open, std::string_view(text).substr(open_end + 1, end - open_end - 1));
  }
}

/// The value of attribute `key` in an opening tag's text, if it has one.
std::optional<std::string> attribute(const std::string& open, const std::string& key) {
  const std::string start = " " + key + "=\"";
  const std::size_t at = open.find(start);
  if (at == std::string::npos)
    return std::nullopt;
  const std::size_t first = at + start.size();
  const std::size_t last = open.find('"', first);
  if (last == std::string::npos)
    return std::nullopt;
  return open.substr(first, last - first);
}

/// A whole-number attribute (digits only, at most 9 of them), or `fallback` when it is absent.
std::uint64_t count_attribute(const std::string& open, const std::string& key,
                              std::optional<std::uint64_t> fallback, const std::string& what,
                              const std::string& name) {
  const std::optional<std::string> v = attribute(open, key);
  if (!v && fallback)
    return *fallback;
  const bool digits =
      v && !v->empty() && v->size() <= 9 && v->find_first_not_of("0123456789") == std::string::npos;
  if (!digits)
    throw InputError(name, "malformed COLLADA file: a <" + what + "> has no whole-number " + key);
  return std::stoull(*v);
}

void check_integer_lists(const std::string& text, const std::string& tag, const std::string& name) {
  each_element(text, tag, name, [&](const std::string&, std::string_view body) {
    for (const char c : body) {
      if (!integer_list_char(c))
        throw InputError(name, "malformed COLLADA file: a <" + tag +
                                   "> list holds a character that is not part of a number");
    }
  });
}

/// Every array has a count, and every accessor reads within the array it names: assimp 5.2 reads
/// an accessor's values without checking them against its array (found by the cfg target: a
/// <float_array> without its count made assimp read through a null pointer).
void check_arrays_and_accessors(const std::string& text, const std::string& name) {
  std::map<std::string, std::uint64_t> counts;  // array id -> its count
  for (const char* tag : {"float_array", "int_array", "bool_array", "Name_array", "IDREF_array"}) {
    each_element(text, tag, name, [&](const std::string& open, std::string_view) {
      const std::uint64_t count = count_attribute(open, "count", std::nullopt, tag, name);
      if (const auto id = attribute(open, "id"))
        counts[*id] = count;
    });
  }
  each_element(text, "accessor", name, [&](const std::string& open, std::string_view body) {
    const std::optional<std::string> source = attribute(open, "source");
    const std::uint64_t count = count_attribute(open, "count", std::nullopt, "accessor", name);
    const std::uint64_t stride = count_attribute(open, "stride", 1, "accessor", name);
    const std::uint64_t offset = count_attribute(open, "offset", 0, "accessor", name);
    const auto array = source && source->size() > 1 && source->front() == '#'
                           ? counts.find(source->substr(1))
                           : counts.end();
    if (array == counts.end())
      throw InputError(name, "malformed COLLADA file: an <accessor> names no array of the file");
    // The last item's values: one per <param> (at least one), within its stride.
    std::uint64_t params = 0;
    for (std::size_t at = body.find("<param"); at != std::string_view::npos;
         at = body.find("<param", at + 1))
      ++params;
    params = std::max<std::uint64_t>(params, 1);
    if (count > 0 && offset + (count - 1) * stride + params > array->second)
      throw InputError(name, "malformed COLLADA file: an <accessor> reads beyond its array '" +
                                 array->first + "'");
  });
}

}  // namespace

void check_collada_lists(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* tag : {"p", "vcount", "h"})
    check_integer_lists(text, tag, file.string());
  check_arrays_and_accessors(text, file.string());
}

}  // namespace tandem
