#pragma once
// JSON forms of the values the journal and the viewer's protocol exchange. Numbers are written by
// nlohmann::json, which prints doubles so that they read back bit for bit.

#include <nlohmann/json.hpp>

#include "tandem/planning/interaction.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

nlohmann::json interaction_json(const InteractionSettings& settings);
/// Every field required; throws nlohmann::json::exception or std::invalid_argument.
InteractionSettings interaction_from_json(const nlohmann::json& j);

/// [x, y, z, qx, qy, qz, qw]
nlohmann::json config_json(const Config& q);
/// Throws std::invalid_argument unless it is an array of 7 numbers (nlohmann's exception for a
/// non-number).
Config config_from_json(const nlohmann::json& j);

}  // namespace tandem
