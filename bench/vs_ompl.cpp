// tandem (its BiRRT, RRT or mixed portfolio: --mode) against OMPL 1.5's planners, side by side on
// OMPL.app's problems.
//
// OMPL is measured as OMPL.app's users run it (ompl_app_setup.hpp): OMPL.app's FCL collision
// model and validity checker, built here from OMPL and FCL directly, OMPL's space, metric,
// DiscreteMotionValidator, projections and planner defaults (the range only where the problem's
// [planner] section gives one). tandem runs with its own collision checker and motion validator.
// Both get the same meshes, start, goal, bounds and motion resolution (tandem's OMPL.app loader),
// and the same time limit. Run i runs every planner once, in an order rotated by i.
//
// Every solved tandem path is re-checked by OMPL (PathGeometric::check() at OMPL.app's
// resolution) and by tandem's check_path.
//
// Output: a table per problem (solved runs, median and p90 times with unsolved runs counted at the
// limit, median validity checks and nodes, the ratios of tandem's median time to RRTConnect's and
// to the best OMPL planner's), optionally the same as a Markdown table and one JSON line per run.

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "bench_report.hpp"
#include "ompl_app_setup.hpp"
#include "parse_arguments.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/runs/run.hpp"
#include "tandem/scene/ompl_app_problem.hpp"

namespace fs = std::filesystem;
using bench::RunResult;

namespace {

struct Options {
  std::string shared = "../shared";
  std::vector<std::string> problems;  ///< empty: every problem of the shared folder
  std::vector<std::string> planners = {"rrtconnect"};
  int runs = 20;
  double time_limit = 30.0;
  double hard_time_limit = 60.0;
  std::uint64_t seed = 1;
  unsigned threads = 1;
  std::string jsonl;
  std::string markdown;
  bool profile = false;
  std::string extend = "classic";
  std::string validation = "exact";
  std::string mode = "birrt+rrt";
};

/// The name of tandem's runs in the results: "tandem-" and its planner.
std::string tandem_name(const Options& o) {
  return "tandem-" + o.mode;
}

/// The registry's planners that plan alone (no operator): tandem's choices for --mode.
std::vector<std::string> planners_alone() {
  std::vector<std::string> names;
  for (const tandem::PlannerEntry& e : tandem::planner_registry()) {
    if (!e.uses_operator)
      names.emplace_back(e.name);
  }
  return names;
}

/// The problems that get --hard-time-limit.
bool is_hard(const std::string& name) {
  return name == "bugtrap" || name == "alpha-1.2";
}

fs::path omplapp_dir(const Options& o) {
  return fs::path(o.shared) / "benchmarks" / "omplapp";
}

/// 3D/NAME.cfg or else 2D/NAME.cfg.
fs::path resolve_problem(const fs::path& dir, const std::string& name) {
  for (const char* sub : {"3D", "2D"}) {
    const fs::path cfg = dir / sub / (name + ".cfg");
    if (fs::is_regular_file(cfg))
      return cfg;
  }
  throw tandem::InputError("--problems", "unknown problem '" + name + "' (no 3D/" + name +
                                             ".cfg or 2D/" + name + ".cfg in " + dir.string() +
                                             ")");
}

/// Every .cfg of 3D/ then 2D/: the known ones from the easiest, then the others by name.
std::vector<std::string> default_problems(const fs::path& dir) {
  static const std::vector<std::string> kOrder = {"Easy",      "cubicles",    "Twistycool",
                                                  "alpha-1.5", "Apartment",   "bugtrap",
                                                  "alpha-1.2", "Maze_planar", "BugTrap_planar"};
  std::vector<std::string> names;
  for (const char* sub : {"3D", "2D"}) {
    std::vector<std::string> found;
    if (fs::is_directory(dir / sub)) {
      for (const auto& entry : fs::directory_iterator(dir / sub)) {
        if (entry.path().extension() == ".cfg")
          found.push_back(entry.path().stem().string());
      }
    }
    auto rank = [](const std::string& n) {
      return std::find(kOrder.begin(), kOrder.end(), n) - kOrder.begin();
    };
    std::sort(found.begin(), found.end(), [&](const std::string& a, const std::string& b) {
      return rank(a) != rank(b) ? rank(a) < rank(b) : a < b;
    });
    names.insert(names.end(), found.begin(), found.end());
  }
  if (names.empty())
    throw tandem::InputError("--shared", "no OMPL.app problems in " + dir.string());
  return names;
}

void check_planners(const std::vector<std::string>& planners) {
  const auto& known = bench::ompl_planner_names();
  std::set<std::string> seen;
  for (const std::string& p : planners) {
    if (std::find(known.begin(), known.end(), p) == known.end()) {
      std::string list;
      for (const std::string& k : known)
        list += (list.empty() ? "" : ", ") + k;
      throw tandem::InputError("--planners", "unknown planner '" + p + "' (known: " + list + ")");
    }
    if (!seen.insert(p).second)
      throw tandem::InputError("--planners", "planner '" + p + "' given twice");
  }
}

struct TandemRun {
  RunResult result;
  tandem::Path path;
};

/// tandem's side: its planner (--mode) with its own collision checker, as `tandem plan` runs it
/// (with --threads above 1, its portfolio of searches).
TandemRun run_tandem(const tandem::Problem& problem, tandem::CollisionChecker& checker,
                     double range, std::uint64_t seed, double time_limit, const Options& o) {
  tandem::RunSpec spec;
  spec.mode = o.mode;
  spec.settings.extend =
      o.extend == "last-valid" ? tandem::ExtendMode::last_valid : tandem::ExtendMode::classic;
  spec.settings.validation = *tandem::parse_motion_validation(o.validation);
  spec.settings.seed = seed;
  spec.settings.range = range;
  spec.settings.profile = o.profile;
  spec.settings.threads = o.threads;
  spec.time_limit = time_limit;
  const tandem::Stopwatch watch;
  const tandem::RunOutcome outcome = tandem::execute_run(problem, spec, checker);
  TandemRun run;
  RunResult& r = run.result;
  r.planner = tandem_name(o);
  r.threads = o.threads;
  r.member = outcome.member;
  r.range = outcome.range;
  r.time_s = watch.seconds();
  r.solved = outcome.status == tandem::PlannerStatus::solved;
  r.checks = outcome.stats.collision_checks;
  r.nodes = outcome.stats.nodes;
  r.collision_time_s = outcome.stats.collision_time_s;
  r.nearest_time_s = outcome.stats.nearest_time_s;
  if (r.solved) {
    run.path = outcome.path;
    r.path_length = outcome.path_length;
  }
  return run;
}

void write_json_line(std::ostream& out, const std::string& problem, int run, std::uint64_t seed,
                     double limit, const RunResult& r, const nlohmann::json& path_checks) {
  nlohmann::json line{{"problem", problem},
                      {"planner", r.planner},
                      {"threads", r.threads},
                      {"member", r.member},
                      {"run", run},
                      {"seed", seed},
                      {"solved", r.solved},
                      {"time_s", r.time_s},
                      {"collision_checks", r.checks},
                      {"nodes", r.nodes},
                      {"range", r.range},
                      {"path_length", r.path_length},
                      {"time_limit_s", limit},
                      {"collision_time_s", r.collision_time_s},
                      {"nearest_time_s", r.nearest_time_s}};
  if (!path_checks.is_null())
    line["path_checks"] = path_checks;
  out << line.dump() << '\n' << std::flush;
}

void check_same_extent(const bench::OmplAppProblem& ompl, const tandem::Problem& problem) {
  const double theirs = ompl.space_information()->getMaximumExtent();
  const double ours = problem.space.max_extent();
  if (std::abs(theirs - ours) > 1e-9 * ours) {
    throw std::logic_error("OMPL's maximum extent (" + std::to_string(theirs) +
                           ") is not tandem's (" + std::to_string(ours) + ") for " + problem.name);
  }
}

void print_profile(const std::vector<RunResult>& runs) {
  double total = 0, coll = 0, nn = 0;
  // Shares of the threads' time: a portfolio's query times add up over its members.
  for (const RunResult& r : runs) {
    total += r.time_s * r.threads;
    coll += r.collision_time_s;
    nn += r.nearest_time_s;
  }
  std::printf(
      "  tandem profile (of its threads' time): collision checks %.1f%%, nearest neighbour "
      "%.1f%%, the rest %.1f%%\n",
      100 * coll / total, 100 * nn / total, 100 * (total - coll - nn) / total);
}

/// One problem: every planner `runs` times, alternating; the runs go to `lines` as they end.
class ProblemBench {
 public:
  ProblemBench(const std::string& name, const fs::path& cfg, const Options& o)
      : name_(name),
        o_(o),
        problem_(tandem::load_ompl_app_problem(cfg)),
        limit_(is_hard(name) ? o.hard_time_limit : o.time_limit),
        checker_(problem_.scene),
        validator_(problem_.space, checker_),
        exact_(problem_.space, checker_, {tandem::MotionValidation::exact, 0.0}),
        ompl_(problem_) {
    check_same_extent(ompl_, problem_);
    for (const std::string& p : o.planners) {
      runners_.push_back(std::make_unique<bench::OmplPlannerRunner>(ompl_, p, o.threads,
                                                                    bench::cfg_range(problem_, p)));
    }
  }

  bench::ProblemReport run(std::ostream* lines) {
    const std::size_t n = 1 + runners_.size();
    for (int i = 0; i < o_.runs; ++i) {
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t who = (static_cast<std::size_t>(i) + k) % n;
        if (who == 0)
          run_tandem_once(i, lines);
        else
          record(i, o_.seed, runners_[who - 1]->run(limit_), nullptr, lines);
      }
    }
    return report();
  }

  const std::vector<RunResult>& tandem_runs() { return results_[tandem_name(o_)]; }

 private:
  void run_tandem_once(int i, std::ostream* lines) {
    // The range the problem's [planner] section gives tandem's planner, as `tandem plan` reads it.
    auto hint = problem_.hints.range.find(std::string(tandem::find_planner(o_.mode)->ompl_range));
    const double range =
        hint != problem_.hints.range.end() ? hint->second : problem_.space.default_range();
    const std::uint64_t seed = o_.seed + static_cast<std::uint64_t>(i);
    TandemRun t = run_tandem(problem_, checker_, range, seed, limit_, o_);
    nlohmann::json checks;
    if (t.result.solved) {
      const bool ompl_ok = ompl_.check_path(t.path);
      // tandem's exact check, whatever the run's validation was.
      const bool tandem_ok = tandem::check_path(t.path, exact_).valid;
      ++paths_.checked;
      paths_.ompl_failures += ompl_ok ? 0 : 1;
      paths_.tandem_failures += tandem_ok ? 0 : 1;
      checks = {{"ompl", ompl_ok}, {"tandem", tandem_ok}};
    }
    record(i, seed, std::move(t.result), checks, lines);
  }

  void record(int i, std::uint64_t seed, RunResult r, const nlohmann::json& checks,
              std::ostream* lines) {
    if (lines != nullptr)
      write_json_line(*lines, name_, i, seed, limit_, r, checks);
    results_[r.planner].push_back(std::move(r));
  }

  bench::ProblemReport report() {
    bench::ProblemReport rep;
    rep.problem = name_;
    rep.time_limit = limit_;
    rep.runs = o_.runs;
    rep.tandem = bench::summarize(results_[tandem_name(o_)], limit_);
    for (const auto& runner : runners_)
      rep.ompl.push_back(bench::summarize(results_[runner->label()], limit_));
    rep.paths = paths_;
    return rep;
  }

  std::string name_;
  const Options& o_;
  tandem::Problem problem_;
  double limit_;
  tandem::CollisionChecker checker_;
  /// Builds the checker's distance grid once, before the timed runs (as a user's session would).
  tandem::MotionValidator validator_;
  tandem::MotionValidator exact_;
  bench::OmplAppProblem ompl_;
  std::vector<std::unique_ptr<bench::OmplPlannerRunner>> runners_;
  std::map<std::string, std::vector<RunResult>> results_;
  bench::PathChecks paths_;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("--shared", o.shared, "The shared folder holding benchmarks/omplapp");
  app.add_option("--problems", o.problems,
                 "OMPL.app problems (3D/NAME.cfg or 2D/NAME.cfg); default: all of them")
      ->delimiter(',');
  app.add_option("--planners", o.planners,
                 "OMPL planners: rrtconnect, kpiece1, bkpiece1, lbkpiece1, biest, sbl, prrt, "
                 "parallel-rrtconnect (tandem always runs)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--runs", o.runs, "Runs per planner and problem")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--time-limit", o.time_limit, "Seconds per run")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--hard-time-limit", o.hard_time_limit, "Seconds per run on bugtrap, alpha-1.2")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--seed", o.seed, "tandem's run i uses seed + i; OMPL is seeded once with it")
      ->capture_default_str();
  app.add_option("--threads", o.threads,
                 "Threads of tandem (its portfolio), prrt and parallel-rrtconnect")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--jsonl", o.jsonl, "Also write one JSON line per run here");
  app.add_option("--markdown", o.markdown, "Also write the summary as a Markdown table here");
  app.add_flag("--profile", o.profile,
               "Time tandem's collision checks and nearest-neighbour queries");
  app.add_option("--validation", o.validation,
                 "tandem's motion validation: discrete (as OMPL's) or exact (whole motions)")
      ->check(CLI::IsMember({"discrete", "exact"}))
      ->capture_default_str();
  app.add_option("--mode", o.mode,
                 "tandem's planner: birrt, rrt or birrt+rrt (on one thread, birrt+rrt is birrt)")
      ->check(CLI::IsMember(planners_alone()))
      ->capture_default_str();
  app.add_option("--extend", o.extend, "tandem's extension: classic or last-valid")
      ->check(CLI::IsMember({"classic", "last-valid"}))
      ->capture_default_str();
}

int run_benchmark(const Options& o) {
  const fs::path dir = omplapp_dir(o);
  check_planners(o.planners);
  const std::vector<std::string> names = o.problems.empty() ? default_problems(dir) : o.problems;
  std::vector<fs::path> cfgs;
  for (const std::string& name : names)
    cfgs.push_back(resolve_problem(dir, name));

  std::ofstream lines, markdown;
  if (!o.jsonl.empty())
    lines.open(o.jsonl);
  if (!o.markdown.empty()) {
    markdown.open(o.markdown);
    bench::write_markdown_header(markdown);
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    ProblemBench problem(names[i], cfgs[i], o);
    const bench::ProblemReport report = problem.run(lines.is_open() ? &lines : nullptr);
    bench::print_report(stdout, report);
    if (o.profile)
      print_profile(problem.tandem_runs());
    if (markdown.is_open())
      bench::write_markdown_row(markdown, report);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tandem against OMPL's planners as OMPL.app runs them, runs alternating"};
  Options o;
  add_options(app, o);
  if (const auto code = bench::parse_arguments(app, argc, argv, "tandem-vs-ompl"))
    return *code;

  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  ompl::RNG::setSeed(o.seed);  // once, before OMPL makes its first generator
  try {
    return run_benchmark(o);
  } catch (const tandem::InputError& e) {
    std::cerr << "tandem-vs-ompl: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "tandem-vs-ompl: internal error: " << e.what() << '\n';
    return 1;
  }
}
