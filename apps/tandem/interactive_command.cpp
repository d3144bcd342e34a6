// tandem interactive and tandem demo: a live session, the planner thread and the operator thread
// together, journaled for exact replay, with the web viewer served from this process.

#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <thread>

#include "cli_support.hpp"
#include "commands.hpp"
#include "part_picker.hpp"
#include "run_options.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/scene/cad_loader.hpp"
#include "tandem/session/live_session.hpp"
#include "tandem/web/viewer_server.hpp"
#include "viewer_options.hpp"

namespace tandem::cli {
namespace {

struct InteractiveArgs {
  RunArgs run;
  ViewerArgs viewer;
  bool headless = false;
  bool paused = false;
  bool exit_when_done = false;
  std::optional<double> linger;  ///< seconds to wait for a browser after the planner ends
  /// With the viewer: the session (the planner and the simulated operator) starts when the first
  /// browser connects (or after --linger seconds without one), so that a person sees the trees
  /// grow from the start.
  bool wait_for_browser = false;
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

/// What the browser may do to a live session.
///
/// Threading: handle() and connected() on the server's thread, browser_came() on any.
class LiveControl final : public ViewerControl {
 public:
  explicit LiveControl(LiveSession& session) : session_(session) {}

  /// Whether a browser has connected.
  bool browser_came() const { return browser_came_.load(); }
  void connected() override { browser_came_.store(true); }

  std::optional<std::string> handle(const ClientMessage& m) override {
    switch (m.kind) {
      case ClientMessage::Kind::pose:
        session_.operator_input().set_pose(m.q, m.id);
        return std::nullopt;
      case ClientMessage::Kind::input: {
        std::string why;
        if (!session_.operator_input().select(m.input, &why))
          return why;
        return std::nullopt;
      }
      case ClientMessage::Kind::params:
        session_.set_interaction(m.settings);
        return std::nullopt;
      case ClientMessage::Kind::command:
        if (m.command == "pause")
          session_.pause();
        else if (m.command == "resume")
          session_.resume();
        else if (m.command == "step")
          session_.step_once();
        else
          session_.reset();
        return std::nullopt;
      case ClientMessage::Kind::take_out:
        return "this session already moves its part: a new part needs a new session";
    }
    return "unknown message";
  }
  InteractionSettings settings() const override { return session_.interaction(); }
  std::optional<std::filesystem::path> journal() const override { return session_.journal_file(); }

 private:
  LiveSession& session_;
  std::atomic<bool> browser_came_{false};
};

/// The run a live session makes: a planner that takes an operator, 600 s unless told otherwise.
RunSpec live_spec(InteractiveArgs& args, const Problem& problem) {
  if (!args.run.mode)
    args.run.mode = "interactive-contact";
  RunSpec spec = make_spec(args.run, problem);
  // A problem without a guide (an assembly's part taken out) has no simulated operator: the part
  // waits for the person in the viewer.
  if (problem.guide.empty() && !args.run.tunables.contains("operator"))
    spec.operator_name = "browser";
  require_live_planner(spec);
  if (!args.run.time_limit)
    spec.time_limit = 600.0;
  CollisionChecker checker(problem.scene);
  require_valid_endpoints(problem, checker, validation_settings(spec.settings));
  return spec;
}

LiveOptions live_options(InteractiveArgs& args, const Problem& problem) {
  if (args.session.empty()) {
    args.session = default_session_file(problem);
    std::filesystem::create_directories("sessions");
  }
  LiveOptions options;
  options.problem_name = args.run.problem.problem;
  options.take_out = args.run.problem.take_out;
  options.journal = args.session;
  options.operator_rate_hz = args.operator_rate;
  options.digest_every_s = args.digest_every;
  options.stay = !args.headless && !args.exit_when_done;
  options.start_paused = args.paused;
  return options;
}

/// The viewer of a session: its state, the session's controls and the server, alive together.
struct Viewer {
  Viewer(const Problem& problem, LiveSession& session, const ViewerArgs& args)
      : state(problem, session.spec().mode, false),
        control(session),
        server(state, control, server_options(args)) {
    session.set_observer(&state);
  }
  ViewerState state;
  LiveControl control;
  ViewerServer server;
};

/// The demo's wait before the session: until the first browser connects, --linger seconds at most
/// (or Ctrl-C).
void wait_for_browser(const InteractiveArgs& args, const LiveSession& session,
                      const Viewer& viewer) {
  const Stopwatch watch;
  const double limit = args.linger.value_or(60.0);
  while (!viewer.control.browser_came() && !session.stopping()) {
    if (watch.seconds() > limit) {
      std::cout << "  no browser in " << static_cast<int>(limit) << " s: planning without one\n"
                << std::flush;
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

/// Prints progress each second; once the planner has ended, ends the session after --linger
/// seconds without a browser.
std::function<void(const LiveProgress&)> progress_printer(InteractiveArgs& args,
                                                          LiveSession& session,
                                                          const std::unique_ptr<Viewer>& viewer) {
  auto announced_end = std::make_shared<bool>(false);
  return [&args, &session, &viewer, announced_end](const LiveProgress& p) {
    if (p.status != PlannerStatus::running) {
      if (!*announced_end) {
        *announced_end = true;
        std::cout << "  " << to_string(p.status) << " after " << p.stats.iterations
                  << " iterations, " << p.stats.nodes << " nodes; the viewer shows it until Ctrl-C"
                  << (args.linger ? " (or " + std::to_string(static_cast<int>(*args.linger)) +
                                        " s from now if no browser has connected)"
                                  : std::string())
                  << '\n'
                  << std::flush;
      }
      if (args.linger && viewer && viewer->server.connections() == 0) {
        *args.linger -= 1.0;
        if (*args.linger < 0.0)
          session.stop();
      }
      return;
    }
    if (p.paused)
      return;
    std::cout << "  " << static_cast<int>(p.elapsed_s) << " s: " << p.stats.iterations
              << " iterations (" << static_cast<long>(p.iterations_per_s) << "/s), "
              << p.stats.nodes << " nodes, " << p.stats.collision_checks
              << " collision checks; operator " << static_cast<long>(p.operator_rate_hz) << " Hz\n"
              << std::flush;
  };
}

int finish_session(const InteractiveArgs& args, const Problem& problem, const LiveSession& session,
                   PlannerStatus status) {
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

int run_interactive(InteractiveArgs args) {
  if (!args.headless)
    check_server_options(server_options(args.viewer));
  ProblemArgs& what = args.run.problem;
  if (!args.headless && is_cad_file(what.problem) && what.take_out.part.empty()) {
    const std::optional<std::string> part = pick_part_in_viewer(what, args.viewer);
    if (!part) {
      std::cout << "no part chosen\n";
      return 1;
    }
    what.take_out.part = *part;
  }
  const Problem problem = load_problem(args.run.problem);
  const RunSpec spec = live_spec(args, problem);
  LiveSession session(problem, spec, live_options(args, problem));
  std::cout << "tandem interactive: " << problem.name << ", " << spec.mode << ", seed "
            << spec.settings.seed << "; session journal " << args.session << '\n';
  const OperatorSwitch::Snapshot input = session.operator_input().snapshot();
  if (!input.spacemouse_available)
    std::cout << "  " << input.spacemouse_status << '\n';
  std::unique_ptr<Viewer> viewer;
  if (!args.headless) {
    viewer = std::make_unique<Viewer>(problem, session, args.viewer);
    std::cout << "  viewer: " << viewer->server.url() << "  (Ctrl-C ends the session)\n";
    if (args.wait_for_browser)
      std::cout << "  the planner starts when a browser opens the viewer\n";
  }
  std::cout << std::flush;

  g_session.store(&session);
  std::signal(SIGINT, on_session_signal);
  std::signal(SIGTERM, on_session_signal);
  if (viewer && args.wait_for_browser)
    wait_for_browser(args, session, *viewer);
  const PlannerStatus status = session.run(progress_printer(args, session, viewer));
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  g_session.store(nullptr);
  session.set_observer(nullptr);
  viewer.reset();
  return finish_session(args, problem, session, status);
}

void add_session_options(CLI::App& app, InteractiveArgs& a) {
  add_viewer_options(app, a.viewer);
  app.add_flag("--headless", a.headless, "Run without the web viewer, printing progress");
  app.add_flag("--paused", a.paused, "Start paused (the viewer resumes or steps)");
  app.add_flag("--exit-when-done", a.exit_when_done,
               "With the viewer: end when the planner ends instead of waiting for Ctrl-C");
  app.add_option("--linger", a.linger,
                 "With the viewer: if no browser has connected, end this many seconds after the "
                 "planner ends (default: wait for Ctrl-C; the demo: 60)")
      ->check(CLI::NonNegativeNumber);
}

}  // namespace

Command add_interactive_command(CLI::App& app) {
  auto args = std::make_shared<InteractiveArgs>();
  add_run_options(app, args->run);
  add_session_options(app, *args);
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
      "Serves the web viewer at the URL it prints (127.0.0.1, with a random token): the scene, "
      "both\ntrees growing, the part at q_device, tuning. The operator: a simulated operator "
      "following\nthe problem's guide (experienced, inexperienced), trace:FILE recorded in "
      "seconds, or\nbrowser (the part waits at the start for you); in the viewer you take over "
      "at any time\n(drag the part; keyboard, gamepad, SpaceMouse by WebHID or spacenavd). The "
      "operator runs on\nits own thread on the wall clock; the planner takes its latest state "
      "each iteration.\nEverything the planner saw is journaled as it happens: 'tandem replay "
      "SESSION' rebuilds the\nsame tree. The default mode is interactive-contact, the default "
      "time limit 600 s of\nplanning; Ctrl-C ends the session (its journal is complete). Exit 0 "
      "if solved, 1 if not,\n2 for bad input.");
  return [args] { return run_interactive(*args); };
}

Command add_demo_command(CLI::App& app) {
  auto args = std::make_shared<InteractiveArgs>();
  add_session_options(app, *args);
  app.add_option("--seed", args->run.seed, "The planner's seed (default 1)");
  app.add_option("--session", args->session,
                 "Journal the session here (default sessions/NAME-TIME.jsonl)");
  app.footer(
      "The built-in assembly scene shaft-bores, where the computer alone does not get through in "
      "a\nminute: a shaft slid through the tight bores of two bearing housings, with contact "
      "sampling\n(alpha 0.5). An experienced simulated operator moves the shaft along the scene's "
      "guide until\nyou take over in the viewer (drag the part, or use the keyboard, a gamepad or "
      "a SpaceMouse).\nPrints the viewer's URL; the planner starts when a browser opens it (at "
      "once with --headless,\nafter --linger seconds without one). The viewer counts the nodes "
      "grown toward random samples,\nthe operator and contact samples. Ctrl-C ends the session, "
      "whose journal 'tandem replay'\nreproduces exactly.");
  return [args] {
    args->run.problem.problem = "shaft-bores";
    args->run.mode = "interactive-contact";
    args->wait_for_browser = true;
    if (!args->linger)
      args->linger = 60.0;
    return run_interactive(*args);
  };
}

}  // namespace tandem::cli
