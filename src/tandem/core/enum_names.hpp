#pragma once
// The names of an enum's values, in the enum's order (0, 1, 2, ...), both ways: one list per enum
// instead of a to_string switch and a parse chain that must agree.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace tandem {

template <class Enum, std::size_t N>
struct EnumNames {
  std::array<std::string_view, N> names;

  constexpr std::string_view name(Enum value) const {
    return names[static_cast<std::size_t>(value)];
  }
  constexpr std::optional<Enum> parse(std::string_view text) const {
    for (std::size_t i = 0; i < N; ++i) {
      if (names[i] == text)
        return static_cast<Enum>(i);
    }
    return std::nullopt;
  }
};

}  // namespace tandem
