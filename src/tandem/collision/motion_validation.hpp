#pragma once
// The ways a motion can be checked (MotionValidator, motion_validator.hpp, says how each works),
// apart from the validator so that settings and samplers can name them without its headers.

#include <cstdint>
#include <optional>
#include <string_view>

namespace tandem {

enum class MotionValidation : std::uint8_t { exact, discrete };

/// "exact" or "discrete".
std::string_view to_string(MotionValidation v);
std::optional<MotionValidation> parse_motion_validation(std::string_view name);

/// The clearance, in translation steps, at which an exact last-valid sweep stops in front of an
/// obstacle (MotionValidator::check_motion_last_valid): a configuration closer than this cannot
/// be extended toward the obstacle's side in exact mode.
inline constexpr double kSweepStopSteps = 0.1;

}  // namespace tandem
