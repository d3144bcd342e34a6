// tandem render: an SVG picture of a problem and, optionally, a path.

#include <iostream>

#include "cli_support.hpp"
#include "commands.hpp"
#include "tandem/core/text.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/render/svg_render.hpp"

namespace tandem::cli {

Command add_render_command(CLI::App& app) {
  struct Args {
    ProblemArgs problem;
    std::string path_file;
    std::string out;
  };
  auto args = std::make_shared<Args>();
  add_problem_args(app, args->problem);
  app.add_option("PATHFILE", args->path_file, "A path in OMPL's format to draw");
  app.add_option("--out", args->out, "The SVG file to write")->required();
  return [args]() -> int {
    const Problem problem = load_problem(args->problem);
    Path path;
    if (!args->path_file.empty())
      path = read_path_file(args->path_file, problem.space);
    write_file_atomically(args->out, render_svg(problem, path));
    std::cout << "picture: " << args->out << '\n';
    return 0;
  };
}

}  // namespace tandem::cli
