// tandem interactive: a live session, the planner thread and the operator thread together,
// journaled for exact replay.

#include <csignal>
#include <filesystem>
#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "run_options.hpp"
#include "tandem/core/error.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/session/live_session.hpp"

namespace tandem::cli {
namespace {

struct InteractiveArgs {
  RunArgs run;
  bool headless = false;
  std::string session;
  double operator_rate = 1000.0;
  double digest_every = 2.0;
  std::string out;
};

std::atomic<LiveSession*> g_session{nullptr};

extern "C" void on_session_signal(int) {
  if (LiveSession* s = g_session.load())
    s->stop();
}

/// sessions/NAME-YYYYMMDDTHHMMSSZ.jsonl
std::string default_session_file(const Problem& problem) {
  std::string stamp = utc_now_iso8601();
  std::erase(stamp, '-');
  std::erase(stamp, ':');
  return "sessions/" + problem.name + "-" + stamp + ".jsonl";
}

int run_interactive(InteractiveArgs args) {
  if (!args.headless) {
    throw InputError("tandem interactive",
                     "the web viewer is not part of this build yet: run with --headless");
  }
  const Problem problem = load_problem(args.run.problem);
  if (!args.run.mode)
    args.run.mode = "interactive-contact";
  RunSpec spec = make_spec(args.run, problem);
  if (!is_interactive(spec.mode)) {
    throw InputError("--mode",
                     "a live session needs an interactive mode (interactive, "
                     "interactive-contact or irrt)");
  }
  if (!args.run.time_limit)
    spec.time_limit = 600.0;
  {
    CollisionChecker checker(problem.scene);
    require_valid_endpoints(problem, checker);
  }
  if (args.session.empty()) {
    args.session = default_session_file(problem);
    std::filesystem::create_directories("sessions");
  }
  LiveOptions options;
  options.problem_name = args.run.problem.problem;
  options.journal = args.session;
  options.operator_rate_hz = args.operator_rate;
  options.digest_every_s = args.digest_every;
  LiveSession session(problem, spec, options);
  std::cout << "tandem interactive: " << problem.name << ", " << to_string(spec.mode) << ", seed "
            << spec.settings.seed << "; session journal " << args.session << '\n'
            << std::flush;

  g_session.store(&session);
  std::signal(SIGINT, on_session_signal);
  std::signal(SIGTERM, on_session_signal);
  const PlannerStatus status = session.run([](const LiveProgress& p) {
    std::cout << "  " << static_cast<int>(p.elapsed_s) << " s: " << p.stats.iterations
              << " iterations (" << static_cast<long>(p.iterations_per_s) << "/s), "
              << p.stats.nodes << " nodes, " << p.stats.collision_checks
              << " collision checks; operator " << static_cast<long>(p.operator_rate_hz) << " Hz\n"
              << std::flush;
  });
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  g_session.store(nullptr);

  const PlannerStats& stats = session.planner().stats();
  std::cout << to_string(status) << " after " << stats.iterations << " iterations, " << stats.nodes
            << " nodes (random " << stats.nodes_by_source[1] << ", operator "
            << stats.nodes_by_source[2] << ", contact " << stats.nodes_by_source[3]
            << "); replay with: tandem replay " << args.session << '\n';
  if (status == PlannerStatus::solved && !args.out.empty()) {
    write_path_file(args.out, session.planner().solution(), problem.space);
    std::cout << "path written to " << args.out << '\n';
  }
  return status == PlannerStatus::solved ? 0 : 1;
}

}  // namespace

Command add_interactive_command(CLI::App& app) {
  auto args = std::make_shared<InteractiveArgs>();
  add_run_options(app, args->run);
  app.add_flag("--headless", args->headless, "Run without the web viewer, printing progress");
  app.add_option("--session", args->session,
                 "Journal the session here (default sessions/NAME-TIME.jsonl)");
  app.add_option("--operator-rate", args->operator_rate,
                 "The operator thread's rate, states per second (default 1000)")
      ->check(CLI::Range(1.0, 100000.0));
  app.add_option("--digest-every", args->digest_every,
                 "Seconds between the tree digests the journal records for checking replays "
                 "(default 2)")
      ->check(CLI::PositiveNumber);
  app.add_option("--out", args->out, "Write the path here when solved, in OMPL's path format");
  app.footer(
      "The operator moves on the wall clock (a simulated operator following the problem's guide, "
      "or\ntrace:FILE recorded in seconds) on its own thread; the planner takes its latest state "
      "each\niteration. Everything the planner saw is journaled as it happens: 'tandem replay "
      "SESSION'\nrebuilds the same tree. The default mode is interactive-contact, the default time "
      "limit\n600 s; Ctrl-C ends the session (its journal is complete). Exit 0 if solved, 1 if "
      "not, "
      "2 for\nbad input.");
  return [args] { return run_interactive(*args); };
}

}  // namespace tandem::cli
