#pragma once
// Scenes shipped inside the tandem program (the scenario files of scenes/, embedded at build time).

#include <string_view>
#include <vector>

namespace tandem {

struct BuiltinScene {
  std::string_view name;  ///< the file's stem, e.g. "cluttered-1"
  std::string_view text;  ///< the scenario file
};

const std::vector<BuiltinScene>& builtin_scenes();

}  // namespace tandem
