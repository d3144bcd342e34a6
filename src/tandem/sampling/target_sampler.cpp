#include "tandem/sampling/target_sampler.hpp"

namespace tandem {

std::string_view to_string(NodeSource source) {
  static constexpr std::string_view kNames[] = {"root", "random", "operator", "contact"};
  return kNames[static_cast<std::size_t>(source)];
}

}  // namespace tandem
