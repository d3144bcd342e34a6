#pragma once
// JSON forms of the values the journal, the JSON output and the viewer's protocol exchange.
// Numbers are written by nlohmann::json, which prints doubles so that they read back bit for bit.

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "tandem/core/parameter.hpp"
#include "tandem/interaction/interaction_settings.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

/// A parameter value as JSON (a number, a boolean or a string).
nlohmann::json param_json(const ParamValue& value);
/// A JSON number, boolean or string as a parameter value (integers stay integers); anything else
/// is returned as a text that no numeric or boolean declaration accepts.
ParamValue param_from_json(const nlohmann::json& j);

/// Every field of `settings` that `table` declares, by name.
template <class Settings>
nlohmann::json settings_json(const ParamTable<Settings>& table, const Settings& settings) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& p : table)
    j[std::string(p.spec.name)] = param_json(p.get(settings));
  return j;
}

/// Sets every field `table` declares from `j`: each required and within its declared range.
/// Throws std::invalid_argument naming the field (nlohmann::json::exception for a missing one).
template <class Settings>
void read_settings_json(const ParamTable<Settings>& table, const nlohmann::json& j,
                        Settings& settings) {
  for (const auto& p : table) {
    const std::string name(p.spec.name);
    const ParamValue v = param_from_json(j.at(name));
    if (auto fault = param_fault(p.spec, v))
      throw std::invalid_argument(name + " " + *fault);
    p.set(settings, normalise_param(p.spec, v));
  }
}

/// The declarations as the viewer's tuning panel reads them: name, symbol, label, unit, kind,
/// min, max (null when unbounded), choices, default, help.
nlohmann::json param_spec_json(const ParamSpec& spec, const ParamValue& default_value);

nlohmann::json interaction_json(const InteractionSettings& settings);
/// Every declared field required and within its range; throws std::invalid_argument naming the
/// field (or nlohmann::json::exception for a value of the wrong JSON type).
InteractionSettings interaction_from_json(const nlohmann::json& j);

/// [x, y, z, qx, qy, qz, qw]
nlohmann::json config_json(const Config& q);
/// Throws std::invalid_argument unless it is an array of 7 numbers, a finite position and a unit
/// quaternion (within 1e-6), as config_json writes (nlohmann's exception for a non-number).
Config config_from_json(const nlohmann::json& j);

}  // namespace tandem
