#include "tandem/scene/collada_lists.hpp"

#include <fstream>
#include <iterator>
#include <string>

#include "tandem/core/error.hpp"

namespace tandem {
namespace {

bool integer_list_char(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == ' ' || c == '\t' || c == '\n' ||
         c == '\r';
}

/// Checks the text of every <tag> (or <tag attributes>) element up to its closing tag.
void check_lists(const std::string& text, const std::string& tag, const std::string& name) {
  const std::string close = "</" + tag + ">";
  for (std::size_t at = text.find("<" + tag); at != std::string::npos;
       at = text.find("<" + tag, at + 1)) {
    const std::size_t after = at + 1 + tag.size();
    if (after >= text.size() || (text[after] != '>' && text[after] != ' '))
      continue;  // another element whose name starts the same way
    const std::size_t open_end = text.find('>', after);
    if (open_end == std::string::npos || text[open_end - 1] == '/')
      continue;
    const std::size_t end = text.find(close, open_end);
    if (end == std::string::npos)
      throw InputError(name, "malformed COLLADA file: a <" + tag + "> list is not closed");
    for (std::size_t i = open_end + 1; i < end; ++i) {
      if (!integer_list_char(text[i]))
        throw InputError(name, "malformed COLLADA file: a <" + tag +
                                   "> list holds a character that is not part of a number");
    }
  }
}

}  // namespace

void check_collada_lists(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* tag : {"p", "vcount", "h"})
    check_lists(text, tag, file.string());
}

}  // namespace tandem
