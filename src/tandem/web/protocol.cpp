#include "tandem/web/protocol.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "tandem/io/json_codec.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/space/unit_quaternion.hpp"

namespace tandem {
namespace {

using nlohmann::json;

double finite_number(const json& j, const char* field) {
  if (!j.is_number())
    throw ProtocolError(std::string(field) + " must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v))
    throw ProtocolError(std::string(field) + " must be finite");
  return v;
}

double number_in(const json& j, const char* field, double lo, double hi) {
  const double v = finite_number(j, field);
  if (v < lo || v > hi) {
    throw ProtocolError(std::string(field) + " must be in [" + json(lo).dump() + ", " +
                        json(hi).dump() + "]");
  }
  return v;
}

Config parse_pose(const json& j) {
  if (!j.is_array() || j.size() != 7)
    throw ProtocolError("q must be 7 numbers: x y z qx qy qz qw");
  double v[7];
  for (std::size_t k = 0; k < 7; ++k)
    v[k] = number_in(j[k], "q", -1e9, 1e9);
  Config q;
  q.t = {v[0], v[1], v[2]};
  const std::optional<Eigen::Quaterniond> unit = unit_quaternion(v[6], v[3], v[4], v[5]);
  if (!unit)
    throw ProtocolError("q's quaternion must not be zero");
  q.q = *unit;
  return q;
}

/// A "params" message: every field a declared interaction tunable, within its declared range.
InteractionSettings parse_params(const json& j, InteractionSettings s) {
  bool any = false;
  for (const auto& [key, value] : j.items()) {
    if (key == "type")
      continue;
    any = true;
    const Param<InteractionSettings>* p = find_param(interaction_parameters(), key);
    if (p == nullptr || !p->spec.live)
      throw ProtocolError("unknown parameter '" + key.substr(0, 40) + "'");
    const ParamValue v = param_from_json(value);
    if (auto fault = param_fault(p->spec, v))
      throw ProtocolError(key + " " + *fault);
    p->set(s, normalise_param(p->spec, v));
  }
  if (!any)
    throw ProtocolError("params names no parameter");
  return s;
}

template <class T>
void append(std::string& out, const T* data, std::size_t n) {
  static_assert(std::endian::native == std::endian::little, "the protocol is little endian");
  out.append(reinterpret_cast<const char*>(data), n * sizeof(T));
}

json body_json(const Body& body) {
  json positions = json::array(), indices = json::array();
  const TriangleMesh mesh = body_mesh(body);
  for (const Eigen::Vector3d& p : mesh.vertices)
    for (int k = 0; k < 3; ++k)
      positions.push_back(static_cast<float>(p[k]));
  for (const auto& t : mesh.triangles)
    for (std::uint32_t i : t)
      indices.push_back(i);
  return json{{"name", body.name},
              {"color", {body.color.r, body.color.g, body.color.b, body.color.a}},
              {"positions", std::move(positions)},
              {"indices", std::move(indices)}};
}

}  // namespace

ClientMessage parse_client_message(std::string_view text, const InteractionSettings& current) {
  if (text.size() > kMaxMessageBytes)
    throw ProtocolError("message too long");
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception&) {
    throw ProtocolError("not JSON");
  }
  if (!j.is_object() || !j.contains("type") || !j["type"].is_string())
    throw ProtocolError("a message is a JSON object with a \"type\"");
  const std::string type = j["type"].get<std::string>();
  ClientMessage m;
  if (type == "pose") {
    m.kind = ClientMessage::Kind::pose;
    if (!j.contains("q"))
      throw ProtocolError("pose needs q");
    m.q = parse_pose(j["q"]);
    if (j.contains("id")) {
      if (!j["id"].is_number_unsigned())
        throw ProtocolError("id must be a non-negative integer");
      m.id = j["id"].get<std::uint64_t>();
    }
  } else if (type == "input") {
    m.kind = ClientMessage::Kind::input;
    const auto input = j.contains("input") && j["input"].is_string()
                           ? parse_operator_input(j["input"].get<std::string>())
                           : std::nullopt;
    if (!input)
      throw ProtocolError("input must be simulated, browser or spacemouse");
    m.input = *input;
  } else if (type == "params") {
    m.kind = ClientMessage::Kind::params;
    m.settings = parse_params(j, current);
  } else if (type == "command") {
    m.kind = ClientMessage::Kind::command;
    m.command = j.contains("command") && j["command"].is_string() ? j["command"].get<std::string>()
                                                                  : std::string();
    if (m.command != "pause" && m.command != "resume" && m.command != "step" &&
        m.command != "reset") {
      throw ProtocolError("command must be pause, resume, step or reset");
    }
  } else if (type == "take_out") {
    m.kind = ClientMessage::Kind::take_out;
    if (!j.contains("part") || !j["part"].is_string())
      throw ProtocolError("take_out needs a part (its path in the assembly tree)");
    m.part = j["part"].get<std::string>();
    if (m.part.empty() || m.part.size() > 1024)
      throw ProtocolError("take_out's part must be 1 to 1024 bytes");
  } else {
    throw ProtocolError("unknown message type '" + type.substr(0, 40) + "'");
  }
  return m;
}

json announced_parameters(std::string_view planner, const InteractionSettings& defaults) {
  json list = json::array();
  for (const auto& p : interaction_parameters()) {
    if (p.spec.live && !p.spec.group.empty() && planner_uses(planner, p.spec))
      list.push_back(param_spec_json(p.spec, p.get(defaults)));
  }
  return list;
}

std::string encode_scene(const Problem& problem) {
  json obstacles = json::array();
  for (const Body& body : problem.scene.obstacles)
    obstacles.push_back(body_json(body));
  json guide = json::array();
  for (const Config& q : problem.guide)
    guide.push_back(config_json(q));
  const Bounds& b = problem.space.bounds();
  return json{
      {"name", problem.name},
      {"planar", problem.space.planar()},
      {"bounds",
       {{"min", {b.min.x(), b.min.y(), b.min.z()}}, {"max", {b.max.x(), b.max.y(), b.max.z()}}}},
      {"extent", problem.space.translation_extent()},
      {"start", config_json(problem.start)},
      {"goal", config_json(problem.goal)},
      {"guide", std::move(guide)},
      {"object", body_json(problem.scene.object)},
      {"obstacles", std::move(obstacles)}}
      .dump();
}

std::string encode_nodes(const NodeBatch& batch) {
  const auto count = static_cast<std::uint32_t>(batch.size());
  std::string out;
  out.reserve(16 + 21 * count + 4);
  const std::uint8_t head[4] = {1, batch.tree, 0, 0};
  out.append(reinterpret_cast<const char*>(head), 4);
  append(out, &batch.generation, 1);
  append(out, &batch.first, 1);
  append(out, &count, 1);
  append(out, batch.positions.data(), batch.positions.size());
  append(out, batch.parents.data(), batch.parents.size());
  append(out, batch.sources.data(), batch.sources.size());
  out.append((4 - count % 4) % 4, '\0');
  append(out, batch.labels.data(), batch.labels.size());
  return out;
}

}  // namespace tandem
