#include "tandem/runs/run_record.hpp"

#include <string_view>
#include <type_traits>

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
  r.operator_wait_s = outcome.operator_wait_s;
  r.tree_digest = format_digest(outcome.tree_digest);
  r.threads = outcome.threads;
  r.member = outcome.member;
  return r;
}

std::string RunRecord::param(const std::string& name) const {
  auto it = params.find(name);
  return it == params.end() ? std::string() : it->second;
}

namespace {

/// Every field of a record with its JSON name, the one list both ways use (nodes_by_source, an
/// object by source name, is done apart).
template <class Record, class Visit>
void visit_fields(Record& r, Visit&& field) {
  field("problem", r.problem);
  field("config", r.config);
  field("params", r.params);
  field("seed", r.seed);
  field("time_limit_s", r.time_limit_s);
  field("status", r.status);
  field("solved", r.solved);
  field("path_valid", r.path_valid);
  field("time_s", r.time_s);
  field("iterations", r.iterations);
  field("nodes", r.nodes);
  field("edges", r.edges);
  field("collision_checks", r.collision_checks);
  field("path_length", r.path_length);
  field("operator_iterations", r.operator_iterations);
  field("contact_entries", r.contact_entries);
  field("operator_waits", r.operator_waits);
  field("tree_digest", r.tree_digest);
  field("threads", r.threads);
  field("member", r.member);
  field("operator_wait_s", r.operator_wait_s);
  field("clock", r.clock);
}

/// The fields that records written before them lack, and their value then: operator_waits 0,
/// threads 1, member 0, operator_wait_s 0, clock "virtual".
bool added_later(std::string_view name) {
  return name == "operator_waits" || name == "threads" || name == "member" ||
         name == "operator_wait_s" || name == "clock";
}

template <class T>
T missing_value(std::string_view name) {
  if constexpr (std::is_arithmetic_v<T>)
    return name == "threads" ? T{1} : T{};
  else if constexpr (std::is_same_v<T, std::string>)
    return name == "clock" ? T{"virtual"} : T{};
  else
    return T{};
}

std::string source_name(std::size_t k) {
  return std::string(to_string(static_cast<NodeSource>(k)));
}

}  // namespace

nlohmann::json record_json(const RunRecord& r) {
  nlohmann::json j;
  visit_fields(r, [&](const char* name, const auto& value) { j[name] = value; });
  nlohmann::json sources;
  for (std::size_t k = 0; k < kNodeSources; ++k)
    sources[source_name(k)] = r.nodes_by_source[k];
  j["nodes_by_source"] = sources;
  return j;
}

std::string format_record(const RunRecord& r) {
  return record_json(r).dump();
}

std::optional<RunRecord> parse_record(const std::string& line) {
  try {
    const nlohmann::json j = nlohmann::json::parse(line);
    RunRecord r;
    visit_fields(r, [&](const char* name, auto& value) {
      using T = std::decay_t<decltype(value)>;
      value = added_later(name) && !j.contains(name) ? missing_value<T>(name) : j.at(name).get<T>();
    });
    for (std::size_t k = 0; k < kNodeSources; ++k)
      r.nodes_by_source[k] = j.at("nodes_by_source").at(source_name(k)).get<std::size_t>();
    return r;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

}  // namespace tandem
