#include "tandem/io/json_codec.hpp"

#include <stdexcept>

namespace tandem {

using nlohmann::json;

json interaction_json(const InteractionSettings& i) {
  return json{{"alpha", i.alpha},
              {"contact", i.contact},
              {"contact_samples", i.contact_samples},
              {"contact_distance", i.contact_distance},
              {"contact_clearance", i.contact_clearance},
              {"sampling", std::string(to_string(i.sampling))},
              {"force_mix", i.force_mix},
              {"neighbours", i.neighbours},
              {"sigma", i.sigma},
              {"uniform_every", i.uniform_every}};
}

InteractionSettings interaction_from_json(const json& j) {
  InteractionSettings i;
  i.alpha = j.at("alpha").get<double>();
  i.contact = j.at("contact").get<bool>();
  i.contact_samples = j.at("contact_samples").get<int>();
  i.contact_distance = j.at("contact_distance").get<double>();
  i.contact_clearance = j.at("contact_clearance").get<double>();
  const auto sampling = parse_irrt_sampling(j.at("sampling").get<std::string>());
  if (!sampling)
    throw std::invalid_argument("unknown sampling mode");
  i.sampling = *sampling;
  i.force_mix = j.at("force_mix").get<double>();
  i.neighbours = j.at("neighbours").get<int>();
  i.sigma = j.at("sigma").get<double>();
  i.uniform_every = j.at("uniform_every").get<int>();
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
  return q;
}

}  // namespace tandem
