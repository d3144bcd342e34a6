// tandem: interactive motion planning with contact. Command-line front end.
//
// Exit codes: 0 success; 1 a negative result (no solution within the time limit, an invalid path);
// 2 bad input (a missing or malformed file, an impossible problem, an unknown option or a
// nonsensical value), reported as one line on stderr naming the file or option and the fault.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "tandem/core/error.hpp"

namespace {

constexpr int kBadInput = 2;

int run(int argc, char** argv) {
  CLI::App app{
      "tandem - motion planning for rigid parts through cluttered assemblies, by a planner and a "
      "human\n"
      "operator together (RRT-Connect on SE(3) with FCL collision checking).\n"};
  app.name("tandem");
  app.set_version_flag("--version", "tandem " TANDEM_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 no solution / invalid path, 2 bad input.\n"
      "Run 'tandem COMMAND --help' for a command's options.");

  std::vector<std::pair<CLI::App*, tandem::cli::Command>> commands;
  auto add = [&](const char* name, const char* help, auto adder) {
    CLI::App* sub = app.add_subcommand(name, help);
    commands.emplace_back(sub, adder(*sub));
  };
  add("plan", "Plan a path for a problem and write it in OMPL's path format",
      tandem::cli::add_plan_command);
  add("check-path", "Check every state and motion of a path file against a problem",
      tandem::cli::add_check_path_command);
  add("clearance",
      "How close a path's part comes to the obstacles along the whole motion, and to which",
      tandem::cli::add_clearance_command);
  add("export",
      "A path as an animation (.glb, or an offline .html page) and the part's motion envelope "
      "(.stl)",
      tandem::cli::add_export_command);
  add("scenes", "List the built-in scenes, or print one's scenario file",
      tandem::cli::add_scenes_command);
  add("parts", "List the assembly tree of a STEP or IGES file: names, sizes, colours",
      tandem::cli::add_parts_command);
  add("render", "Draw a problem and optionally a path as an SVG picture",
      tandem::cli::add_render_command);
  add("bench", "Run an experiment (sweeps x seeds): runs, OMPL benchmark log, report",
      tandem::cli::add_bench_command);
  add("interactive", "A live session: planner and operator threads, journaled for exact replay",
      tandem::cli::add_interactive_command);
  add("replay", "Rebuild a live session's tree from its journal and check it is identical",
      tandem::cli::add_replay_command);
  add("demo",
      "The built-in environment 1 live in the web viewer, a simulated operator until you "
      "take over",
      tandem::cli::add_demo_command);

  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    for (const auto& [sub, command] : commands)
      known = known || sub->get_name() == argv[1];
    if (!known) {
      std::cerr << "tandem: error: unknown command '" << argv[1] << "' (see 'tandem --help')\n";
      return kBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "tandem: error: " << e.what() << " (see 'tandem --help')\n";
    return kBadInput;
  }
  for (auto& [sub, command] : commands) {
    if (sub->parsed())
      return command();
  }
  return kBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const tandem::InputError& e) {
    std::cerr << "tandem: error: " << e.what() << '\n';
    return kBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "tandem: error: out of memory\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "tandem: internal error: " << e.what() << '\n';
    return 3;
  }
}
