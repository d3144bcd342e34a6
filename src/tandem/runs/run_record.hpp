#pragma once
// What a run was and what came out of it, as one JSON object: the one encoder of run results, for
// `tandem plan --json` and for the records of experiments (runs.jsonl), which read back.

#include <array>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "tandem/core/parameter.hpp"
#include "tandem/runs/run.hpp"

namespace tandem {

/// One run: what was run and what came out.
struct RunRecord {
  std::string problem;
  std::string config;                         ///< the configuration's label
  std::map<std::string, std::string> params;  ///< the configuration's values, as text
  std::uint64_t seed = 0;
  double time_limit_s = 0.0;
  std::string status;  ///< to_string(PlannerStatus)
  bool solved = false;
  bool path_valid = false;  ///< the solution passed check_path (false when not solved)
  double time_s = 0.0;
  std::uint64_t iterations = 0;
  std::size_t nodes = 0;
  std::size_t edges = 0;
  std::uint64_t collision_checks = 0;
  std::array<std::size_t, kNodeSources> nodes_by_source{};
  double path_length = 0.0;  ///< of the planner's (unsimplified) path; 0 when not solved
  std::uint64_t operator_iterations = 0;
  std::uint64_t contact_entries = 0;
  std::uint64_t operator_waits = 0;  ///< RunOutcome::operator_waits
  double operator_wait_s = 0.0;      ///< RunOutcome::operator_wait_s
  /// The experiment's clock: "virtual" (the operator steps with the planner's iterations) or
  /// "wall" (human time: a simulated person on its own thread, see wall_run.hpp).
  std::string clock = "virtual";
  std::string tree_digest;  ///< hex of RunOutcome::tree_digest
  unsigned threads = 1;     ///< RunOutcome::threads
  unsigned member = 0;      ///< RunOutcome::member

  /// Identifies the run within an experiment: configuration and seed.
  std::string key() const { return config + " #" + std::to_string(seed); }
  /// The value of a parameter as the report shows it ("" if unset).
  std::string param(const std::string& name) const;
};

/// One line of runs.jsonl (no newline).
std::string format_record(const RunRecord& record);
/// nullopt for a line that is not a complete record (e.g. cut short by a kill).
std::optional<RunRecord> parse_record(const std::string& line);

/// The record of a run: `config` labels it ("interactive-contact alpha=0.5"), `params` are the
/// values it was given (as text in the record).
RunRecord make_record(const std::string& problem, const std::string& config,
                      const std::map<std::string, ParamValue>& params, std::uint64_t seed,
                      double time_limit, const RunOutcome& outcome, bool path_valid);

/// The record as JSON (the fields of runs.jsonl).
nlohmann::json record_json(const RunRecord& record);

}  // namespace tandem
