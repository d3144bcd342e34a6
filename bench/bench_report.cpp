#include "bench_report.hpp"

#include <cmath>

#include "bench_stats.hpp"

namespace bench {
namespace {

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string general(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

/// Seconds with about three significant digits.
std::string seconds_text(double s) {
  if (!std::isfinite(s))
    return "n/a";
  return fixed(s, s < 0.1 ? 4 : s < 10.0 ? 3 : 1);
}

std::string solved_text(const PlannerSummary& s) {
  return std::to_string(s.solved) + "/" + std::to_string(s.runs);
}

/// tandem's median over another planner's; below 1 means tandem is faster.
std::string ratio_text(const PlannerSummary& tandem, const PlannerSummary* other) {
  if (other == nullptr || !(other->median_s > 0.0))
    return "n/a";
  return fixed(tandem.median_s / other->median_s, 2);
}

void print_row(std::FILE* out, const PlannerSummary& s) {
  std::fprintf(out, "  %-26s %7u %9.4g %7s %10s %10s %11.0f %10.0f\n", s.planner.c_str(), s.threads,
               s.range, solved_text(s).c_str(), seconds_text(s.median_s).c_str(),
               seconds_text(s.p90_s).c_str(), s.median_checks, s.median_nodes);
}

}  // namespace

PlannerSummary summarize(const std::vector<RunResult>& runs, double time_limit) {
  PlannerSummary s;
  std::vector<double> times, checks, nodes;
  for (const RunResult& r : runs) {
    s.planner = r.planner;
    s.threads = r.threads;
    s.range = r.range;
    ++s.runs;
    s.solved += r.solved ? 1 : 0;
    times.push_back(r.solved ? r.time_s : time_limit);
    checks.push_back(static_cast<double>(r.checks));
    nodes.push_back(static_cast<double>(r.nodes));
  }
  s.median_s = median(times);
  s.p90_s = p90(times);
  s.median_checks = median(checks);
  s.median_nodes = median(nodes);
  return s;
}

const PlannerSummary* ProblemReport::rrtconnect() const {
  for (const PlannerSummary& s : ompl) {
    if (s.planner == "ompl-rrtconnect")
      return &s;
  }
  return nullptr;
}

const PlannerSummary* ProblemReport::best_ompl() const {
  const PlannerSummary* best = nullptr;
  for (const PlannerSummary& s : ompl) {
    if (best == nullptr || s.solved > best->solved ||
        (s.solved == best->solved && s.median_s < best->median_s)) {
      best = &s;
    }
  }
  return best;
}

void print_report(std::FILE* out, const ProblemReport& report) {
  std::fprintf(out, "\n%s: limit %g s, %d runs per planner\n", report.problem.c_str(),
               report.time_limit, report.runs);
  std::fprintf(out, "  %-26s %7s %9s %7s %10s %10s %11s %10s\n", "planner", "threads", "range",
               "solved", "median s", "p90 s", "checks", "nodes");
  print_row(out, report.tandem);
  for (const PlannerSummary& s : report.ompl)
    print_row(out, s);
  const PlannerSummary* best = report.best_ompl();
  std::fprintf(out, "  tandem / ompl-rrtconnect (median time): %s; tandem / best OMPL (%s): %s\n",
               ratio_text(report.tandem, report.rrtconnect()).c_str(),
               best ? best->planner.c_str() : "none", ratio_text(report.tandem, best).c_str());
  std::fprintf(out, "  paths failing OMPL's check: %d of %d (failing tandem's exact check: %d)\n",
               report.paths.ompl_failures, report.paths.checked, report.paths.tandem_failures);
  std::fflush(out);
}

void write_markdown_header(std::ostream& out) {
  out << "| problem | limit (s) | runs | tandem solved | tandem median (s) | tandem p90 (s) "
         "| RRTConnect solved | RRTConnect median (s) | RRTConnect p90 (s) "
         "| best OMPL | best solved | best median (s) | best p90 (s) "
         "| tandem / RRTConnect | tandem / best | tandem paths failing OMPL's check |\n"
      << "|---|--:|--:|--:|--:|--:|--:|--:|--:|---|--:|--:|--:|--:|--:|--:|\n";
}

void write_markdown_row(std::ostream& out, const ProblemReport& report) {
  auto cells = [&out](const PlannerSummary* s) {
    if (s == nullptr) {
      out << " n/a | n/a | n/a |";
      return;
    }
    out << ' ' << solved_text(*s) << " | " << seconds_text(s->median_s) << " | "
        << seconds_text(s->p90_s) << " |";
  };
  const PlannerSummary* best = report.best_ompl();
  out << "| " << report.problem << " | " << general(report.time_limit) << " | " << report.runs
      << " |";
  cells(&report.tandem);
  cells(report.rrtconnect());
  out << ' ' << (best ? best->planner.substr(5) : std::string("n/a")) << " |";
  cells(best);
  out << ' ' << ratio_text(report.tandem, report.rrtconnect()) << " | "
      << ratio_text(report.tandem, best) << " | " << report.paths.ompl_failures << "/"
      << report.paths.checked << " |\n"
      << std::flush;
}

}  // namespace bench
