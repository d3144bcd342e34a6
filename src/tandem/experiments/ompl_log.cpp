#include "tandem/experiments/ompl_log.hpp"

#include <cstdio>
#include <map>
#include <sstream>

namespace tandem {
namespace {

/// OMPL 1.5's ompl::base::PlannerStatus::StatusType, in order, as its Benchmark writes them.
const std::vector<std::string>& status_names() {
  static const std::vector<std::string> kNames = {
      "Unknown status",         "Invalid start", "Invalid goal",
      "Unrecognized goal type", "Timeout",       "Approximate solution",
      "Exact solution",         "Crash",         "Abort"};
  return kNames;
}

int status_index(const std::string& tandem_status) {
  const std::string name = ompl_status_name(tandem_status);
  const auto& names = status_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name)
      return static_cast<int>(i);
  }
  return 0;
}

std::string real(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

/// One line must stay one line in the log.
std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r')
      c = ' ';
  }
  return s;
}

}  // namespace

std::string ompl_status_name(const std::string& s) {
  if (s == "solved")
    return "Exact solution";
  if (s == "timeout" || s == "iteration_limit")
    return "Timeout";
  if (s == "invalid_start")
    return "Invalid start";
  if (s == "invalid_goal")
    return "Invalid goal";
  if (s == "interrupted")
    return "Abort";
  return "Unknown status";
}

namespace {

/// The experiment's part of the log: version, properties, host, the configurations, the limits,
/// the status enum.
void write_experiment(std::ostream& o, const Experiment& experiment, const Problem& problem,
                      const OmplLogHeader& header, std::size_t max_runs) {
  o << "tandem version " << header.version << '\n';
  o << "Experiment " << one_line(experiment.name) << '\n';
  o << "2 experiment properties\n";
  o << "problem VARCHAR(512) = " << one_line(problem.name) << '\n';
  o << "scene_source VARCHAR(1024) = " << one_line(problem.source) << '\n';
  o << "Running on " << one_line(header.hostname.empty() ? "unknown" : header.hostname) << '\n';
  o << "Starting at " << one_line(header.date) << '\n';
  o << "<<<|\n";
  o << "Experiment " << experiment.name << ": " << experiment.description << '\n';
  o << "Problem " << problem.name << " (" << problem.source << ")\n";
  for (const RunConfig& c : experiment.configs)
    o << "Configuration: " << c.label() << '\n';
  o << "|>>>\n";
  if (!header.cpuinfo.empty()) {
    o << "<<<|\n" << header.cpuinfo;
    if (header.cpuinfo.back() != '\n')
      o << '\n';
    o << "|>>>\n";
  }
  o << experiment.seed_start << " is the random seed\n";
  o << real(experiment.time_limit) << " seconds per run\n";
  o << "0 MB per run\n";
  o << max_runs << " runs per planner\n";
  o << real(header.total_time_s) << " seconds spent to collect the data\n";
  o << "1 enum type\n";
  o << "status";
  for (const auto& n : status_names())
    o << '|' << n;
  o << '\n';
}

/// One configuration as an OMPL "planner": its common properties and one line per run.
void write_planner(std::ostream& o, const RunConfig& c, const std::vector<const RunRecord*>& runs) {
  static const char* kProperties[] = {"time REAL",
                                      "solved BOOLEAN",
                                      "status ENUM",
                                      "approximate solution BOOLEAN",
                                      "correct solution BOOLEAN",
                                      "solution length REAL",
                                      "graph states INTEGER",
                                      "graph motions INTEGER",
                                      "iterations INTEGER",
                                      "collision checks INTEGER",
                                      "seed INTEGER",
                                      "nodes random INTEGER",
                                      "nodes operator INTEGER",
                                      "nodes contact INTEGER",
                                      "operator iterations INTEGER",
                                      "contact entries INTEGER"};
  o << "tandem " << one_line(c.label()) << '\n';
  o << c.values.size() << " common properties\n";
  for (const auto& [k, v] : c.values)
    o << k << " = " << one_line(format_param(v)) << '\n';
  o << std::size(kProperties) << " properties for each run\n";
  for (const char* p : kProperties)
    o << p << '\n';
  o << runs.size() << " runs\n";
  for (const RunRecord* r : runs) {
    const auto src = [&](NodeSource s) { return r->nodes_by_source[static_cast<std::size_t>(s)]; };
    o << real(r->time_s) << "; " << (r->solved ? 1 : 0) << "; " << status_index(r->status)
      << "; 0; " << (r->path_valid ? 1 : 0) << "; " << (r->solved ? real(r->path_length) : "")
      << "; " << r->nodes << "; " << r->edges << "; " << r->iterations << "; "
      << r->collision_checks << "; " << r->seed << "; " << src(NodeSource::random) << "; "
      << src(NodeSource::operator_) << "; " << src(NodeSource::contact) << "; "
      << r->operator_iterations << "; " << r->contact_entries << "; \n";
  }
  o << ".\n";
}

}  // namespace

std::string format_ompl_log(const Experiment& experiment, const Problem& problem,
                            const std::vector<RunRecord>& records, const OmplLogHeader& header) {
  std::map<std::string, std::vector<const RunRecord*>> by_config;
  std::size_t max_runs = 0;
  for (const RunRecord& r : records)
    by_config[r.config].push_back(&r);
  for (const auto& [k, v] : by_config)
    max_runs = std::max(max_runs, v.size());
  std::ostringstream o;
  write_experiment(o, experiment, problem, header, max_runs);
  std::size_t planners = 0;
  for (const RunConfig& c : experiment.configs)
    planners += by_config.count(c.label());
  o << planners << " planners\n";
  for (const RunConfig& c : experiment.configs) {
    auto it = by_config.find(c.label());
    if (it != by_config.end())
      write_planner(o, c, it->second);
  }
  return o.str();
}

}  // namespace tandem
