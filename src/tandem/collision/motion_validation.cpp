#include "tandem/collision/motion_validation.hpp"

#include "tandem/core/enum_names.hpp"

namespace tandem {
namespace {

constexpr EnumNames<MotionValidation, 2> kValidationNames{{"exact", "discrete"}};

}  // namespace

std::string_view to_string(MotionValidation v) {
  return kValidationNames.name(v);
}

std::optional<MotionValidation> parse_motion_validation(std::string_view name) {
  return kValidationNames.parse(name);
}

}  // namespace tandem
