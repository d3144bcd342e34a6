#include "tandem/runs/run_record.hpp"

#include "tandem/core/digest.hpp"

namespace tandem {

RunRecord make_record(const std::string& problem, const std::string& config,
                      const std::map<std::string, ParamValue>& params, std::uint64_t seed,
                      double time_limit, const RunOutcome& outcome, bool path_valid) {
  RunRecord r;
  r.problem = problem;
  r.config = config;
  for (const auto& [k, v] : params)
    r.params[k] = format_param(v);
  r.seed = seed;
  r.time_limit_s = time_limit;
  r.status = std::string(to_string(outcome.status));
  r.solved = outcome.status == PlannerStatus::solved;
  r.path_valid = path_valid;
  const PlannerStats& s = outcome.stats;
  r.time_s = s.time_s;
  r.iterations = s.iterations;
  r.nodes = s.nodes;
  r.edges = s.edges;
  r.collision_checks = s.collision_checks;
  r.nodes_by_source = s.nodes_by_source;
  r.path_length = outcome.path_length;
  r.operator_iterations = s.operator_iterations;
  r.contact_entries = s.contact_entries;
  r.operator_waits = outcome.operator_waits;
  r.tree_digest = format_digest(outcome.tree_digest);
  return r;
}

std::string RunRecord::param(const std::string& name) const {
  auto it = params.find(name);
  return it == params.end() ? std::string() : it->second;
}

nlohmann::json record_json(const RunRecord& r) {
  nlohmann::json j;
  j["problem"] = r.problem;
  j["config"] = r.config;
  j["params"] = r.params;
  j["seed"] = r.seed;
  j["time_limit_s"] = r.time_limit_s;
  j["status"] = r.status;
  j["solved"] = r.solved;
  j["path_valid"] = r.path_valid;
  j["time_s"] = r.time_s;
  j["iterations"] = r.iterations;
  j["nodes"] = r.nodes;
  j["edges"] = r.edges;
  j["collision_checks"] = r.collision_checks;
  nlohmann::json sources;
  for (std::size_t k = 0; k < kNodeSources; ++k)
    sources[std::string(to_string(static_cast<NodeSource>(k)))] = r.nodes_by_source[k];
  j["nodes_by_source"] = sources;
  j["path_length"] = r.path_length;
  j["operator_iterations"] = r.operator_iterations;
  j["contact_entries"] = r.contact_entries;
  j["operator_waits"] = r.operator_waits;
  j["tree_digest"] = r.tree_digest;
  return j;
}

std::string format_record(const RunRecord& r) {
  return record_json(r).dump();
}

std::optional<RunRecord> parse_record(const std::string& line) {
  try {
    const nlohmann::json j = nlohmann::json::parse(line);
    RunRecord r;
    r.problem = j.at("problem").get<std::string>();
    r.config = j.at("config").get<std::string>();
    r.params = j.at("params").get<std::map<std::string, std::string>>();
    r.seed = j.at("seed").get<std::uint64_t>();
    r.time_limit_s = j.at("time_limit_s").get<double>();
    r.status = j.at("status").get<std::string>();
    r.solved = j.at("solved").get<bool>();
    r.path_valid = j.at("path_valid").get<bool>();
    r.time_s = j.at("time_s").get<double>();
    r.iterations = j.at("iterations").get<std::uint64_t>();
    r.nodes = j.at("nodes").get<std::size_t>();
    r.edges = j.at("edges").get<std::size_t>();
    r.collision_checks = j.at("collision_checks").get<std::uint64_t>();
    for (std::size_t k = 0; k < kNodeSources; ++k) {
      r.nodes_by_source[k] = j.at("nodes_by_source")
                                 .at(std::string(to_string(static_cast<NodeSource>(k))))
                                 .get<std::size_t>();
    }
    r.path_length = j.at("path_length").get<double>();
    r.operator_iterations = j.at("operator_iterations").get<std::uint64_t>();
    r.contact_entries = j.at("contact_entries").get<std::uint64_t>();
    r.operator_waits = j.value("operator_waits", std::uint64_t{0});
    r.tree_digest = j.at("tree_digest").get<std::string>();
    return r;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

}  // namespace tandem
