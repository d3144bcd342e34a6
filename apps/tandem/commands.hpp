#pragma once
// The subcommands of the `tandem` program. Each registers its options on a CLI11 subcommand and
// returns the function that runs it; the function returns the process exit code (0 success, 1 a
// negative result such as an invalid path or no solution, 2 bad input) and lets InputError escape
// to main().

#include <CLI/CLI.hpp>
#include <functional>

namespace tandem::cli {

using Command = std::function<int()>;

Command add_plan_command(CLI::App& app);
Command add_check_path_command(CLI::App& app);
Command add_scenes_command(CLI::App& app);
Command add_parts_command(CLI::App& app);
Command add_clearance_command(CLI::App& app);
Command add_export_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_interactive_command(CLI::App& app);
Command add_replay_command(CLI::App& app);
Command add_demo_command(CLI::App& app);

}  // namespace tandem::cli
