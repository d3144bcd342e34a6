// tandem replay: rebuild a live session's tree from its journal, exactly.

#include <atomic>
#include <chrono>
#include <csignal>
#include <iostream>
#include <thread>

#include "cli_support.hpp"
#include "commands.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/session/replay.hpp"
#include "tandem/web/viewer_server.hpp"
#include "viewer_options.hpp"

namespace tandem::cli {
namespace {

struct ReplayArgs {
  std::string session;
  std::vector<std::string> allowed_dirs;
  std::string out;
  bool serve = false;
  ViewerArgs viewer;
  double speed = 1.0;
  bool exit_when_done = false;
};

/// A replay is watched, not steered.
class ReadOnlyControl final : public ViewerControl {
 public:
  explicit ReadOnlyControl(InteractionSettings settings) : settings_(settings) {}
  std::optional<std::string> handle(const ClientMessage&) override {
    return "this is a replay: it shows the recorded session and takes no input";
  }
  InteractionSettings settings() const override { return settings_; }
  std::optional<std::filesystem::path> journal() const override { return std::nullopt; }

 private:
  InteractionSettings settings_;
};

std::atomic<bool> g_stop{false};
extern "C" void on_replay_signal(int) {
  g_stop.store(true);
}

int run_replay(const ReplayArgs& args) {
  if (args.serve)
    check_server_options(server_options(args.viewer));
  const Journal journal = read_journal(args.session);
  ProblemArgs problem_args;
  problem_args.problem = journal.header.problem;
  problem_args.take_out = journal.header.take_out;
  problem_args.allowed_dirs = args.allowed_dirs;
  const Problem problem = load_problem(problem_args);
  if (journal.digests.empty()) {
    std::cout << args.session << ": no tree digest recorded yet (the session ended in its first "
              << "seconds): nothing to replay\n";
    return 1;
  }
  std::optional<ViewerState> state;
  std::optional<ReadOnlyControl> control;
  std::optional<ViewerServer> server;
  ReplayStep on_step;
  const Stopwatch watch;
  double next_update = 0.0;
  std::uint64_t steps = 0;
  if (args.serve) {
    state.emplace(problem, journal.header.mode, true);
    control.emplace(journal.header.settings.interaction);
    server.emplace(*state, *control, server_options(args.viewer));
    std::cout << "viewer: " << server->url() << "  (Ctrl-C ends)\n" << std::flush;
    std::signal(SIGINT, on_replay_signal);
    std::signal(SIGTERM, on_replay_signal);
    // At the recorded pace (the operator's clock), times --speed; 0: as fast as possible.
    on_step = [&](const Planner& planner, const OperatorState* op, bool last) {
      ++steps;
      if (args.speed > 0.0 && op != nullptr && (steps & 31) == 0) {
        const double lead = op->time / args.speed - watch.seconds();
        if (lead > 0.0)
          std::this_thread::sleep_for(std::chrono::duration<double>(std::min(lead, 1.0)));
      }
      const double t = watch.seconds();
      if (t >= next_update || last) {
        state->update(planner, replay_status_json(planner, journal.header.mode, t, last),
                      operator_json(op, planner.settings().interaction, problem.space, nullptr));
        next_update = t + 1.0 / 30.0;
      }
    };
  }
  const ReplayResult r = replay_journal(problem, journal, on_step, [&] {
    if (state)
      state->restarted();
  });
  std::cout << args.session << ": replayed " << r.steps << " steps, " << r.stats.iterations
            << " iterations, " << r.stats.nodes << " nodes; " << to_string(r.status) << "; tree "
            << r.digest;
  if (journal.torn)
    std::cout << " (the journal's last line was cut short: the session was killed)";
  std::cout << '\n';
  if (r.status == PlannerStatus::solved && !args.out.empty())
    write_path_file(args.out, r.solution, problem.space);
  const bool matched = r.matched();
  if (!matched)
    std::cout << "different from the session's tree at step " << *r.mismatch_at << '\n';
  else
    std::cout << "identical to the session's tree (" << r.digests_checked
              << " recorded digests checked)\n";
  if (server && !args.exit_when_done) {
    std::cout << "the viewer shows the replayed session; Ctrl-C ends\n" << std::flush;
    while (!g_stop.load())
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return matched ? 0 : 1;
}

}  // namespace

Command add_replay_command(CLI::App& app) {
  auto args = std::make_shared<ReplayArgs>();
  app.add_option("SESSION", args->session, "A session journal written by tandem interactive")
      ->required();
  app.add_option("--allow-dir", args->allowed_dirs,
                 "A folder the problem may read meshes and URDFs from, besides its own");
  app.add_option("--out", args->out, "Write the replayed path here, if it solved");
  app.add_flag("--serve", args->serve, "Show the replay in the web viewer");
  add_viewer_options(app, args->viewer);
  app.add_option("--speed", args->speed,
                 "With --serve: times the recorded pace (default 1; 0: as fast as possible)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--exit-when-done", args->exit_when_done,
               "With --serve: end when the replay ends instead of waiting for Ctrl-C");
  app.footer(
      "Runs the session's planner again in virtual time with the operator states it used, at the\n"
      "iterations it used them, and its parameter changes, and checks the tree digests the "
      "journal\n"
      "recorded. Exit 0 if the tree is identical, 1 if it is not, 2 for bad input.");
  return [args] { return run_replay(*args); };
}

}  // namespace tandem::cli
