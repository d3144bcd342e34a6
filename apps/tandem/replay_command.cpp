// tandem replay: rebuild a live session's tree from its journal, exactly.

#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/session/replay.hpp"

namespace tandem::cli {
namespace {

struct ReplayArgs {
  std::string session;
  std::vector<std::string> allowed_dirs;
  std::string out;
};

int run_replay(const ReplayArgs& args) {
  const Journal journal = read_journal(args.session);
  ProblemArgs problem_args;
  problem_args.problem = journal.header.problem;
  problem_args.allowed_dirs = args.allowed_dirs;
  const Problem problem = load_problem(problem_args);
  if (journal.digests.empty()) {
    std::cout << args.session << ": no tree digest recorded yet (the session ended in its first "
              << "seconds): nothing to replay\n";
    return 1;
  }
  const ReplayResult r = replay_journal(problem, journal);
  std::cout << args.session << ": replayed " << r.steps << " steps, " << r.stats.iterations
            << " iterations, " << r.stats.nodes << " nodes; " << to_string(r.status) << "; tree "
            << r.digest;
  if (journal.torn)
    std::cout << " (the journal's last line was cut short: the session was killed)";
  std::cout << '\n';
  if (r.status == PlannerStatus::solved && !args.out.empty())
    write_path_file(args.out, r.solution, problem.space);
  if (!r.matched()) {
    std::cout << "different from the session's tree at step " << *r.mismatch_at << '\n';
    return 1;
  }
  std::cout << "identical to the session's tree (" << r.digests_checked
            << " recorded digests checked)\n";
  return 0;
}

}  // namespace

Command add_replay_command(CLI::App& app) {
  auto args = std::make_shared<ReplayArgs>();
  app.add_option("SESSION", args->session, "A session journal written by tandem interactive")
      ->required();
  app.add_option("--allow-dir", args->allowed_dirs,
                 "A folder the problem may read meshes and URDFs from, besides its own");
  app.add_option("--out", args->out, "Write the replayed path here, if it solved");
  app.footer(
      "Runs the session's planner again in virtual time with the operator states it used, at the\n"
      "iterations it used them, and its parameter changes, and checks the tree digests the "
      "journal\n"
      "recorded. Exit 0 if the tree is identical, 1 if it is not, 2 for bad input.");
  return [args] { return run_replay(*args); };
}

}  // namespace tandem::cli
