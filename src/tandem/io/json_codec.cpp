#include "tandem/io/json_codec.hpp"

#include <cmath>

namespace tandem {

using nlohmann::json;

json param_json(const ParamValue& value) {
  return std::visit([](const auto& v) { return json(v); }, value);
}

ParamValue param_from_json(const json& j) {
  if (j.is_number_integer())
    return j.get<std::int64_t>();
  if (j.is_number())
    return j.get<double>();
  if (j.is_boolean())
    return j.get<bool>();
  if (j.is_string())
    return j.get<std::string>();
  return std::string("<") + j.type_name() + ">";
}

json param_spec_json(const ParamSpec& spec, const ParamValue& default_value) {
  json j{
      {"name", spec.name}, {"symbol", spec.symbol},        {"label", spec.label},
      {"unit", spec.unit}, {"kind", to_string(spec.kind)}, {"default", param_json(default_value)},
      {"help", spec.help}};
  if (spec.kind == ParamKind::real || spec.kind == ParamKind::integer) {
    j["min"] = std::isfinite(spec.min) ? json(spec.min) : json(nullptr);
    j["max"] = std::isfinite(spec.max) ? json(spec.max) : json(nullptr);
    j["min_open"] = spec.min_open;
  }
  if (spec.kind == ParamKind::choice)
    j["choices"] = spec.choices;
  return j;
}

json interaction_json(const InteractionSettings& i) {
  return settings_json(interaction_parameters(), i);
}

InteractionSettings interaction_from_json(const json& j) {
  InteractionSettings i;
  read_settings_json(interaction_parameters(), j, i);
  return i;
}

json config_json(const Config& q) {
  return json::array({q.t.x(), q.t.y(), q.t.z(), q.q.x(), q.q.y(), q.q.z(), q.q.w()});
}

Config config_from_json(const json& j) {
  if (!j.is_array() || j.size() != 7)
    throw std::invalid_argument("a pose is 7 numbers");
  Config q;
  q.t = {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
  q.q = Eigen::Quaterniond(j[6].get<double>(), j[3].get<double>(), j[4].get<double>(),
                           j[5].get<double>());
  // Read back bit for bit, so not normalised: a pose that is not a unit quaternion was not written
  // by config_json (FCL asserts on the transform of a huge one: a finding of the journal target).
  if (!q.t.allFinite() || !(std::abs(q.q.norm() - 1.0) <= 1e-6))
    throw std::invalid_argument("a pose is x y z and a unit quaternion qx qy qz qw");
  return q;
}

}  // namespace tandem
