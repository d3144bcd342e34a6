// The human loop's rate: how many operator states a second the operator thread can compute on the
// papers' scenes — read the device (a simulated operator following the scene's guide), find the
// nearest obstacle (FCL distance against every obstacle, with the nearest points) and build the
// contact frame. The papers' operator thread must keep up with a 1 kHz device. A benchmark, not a
// test: it prints a table.
//
//   build/bench/tandem-operator-loop [--seconds S]

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "guide_walk.hpp"
#include "parse_arguments.hpp"
#include "tandem/scene/builtin_scenes.hpp"
#include "tandem/scene/problem_loader.hpp"

int main(int argc, char** argv) {
  CLI::App app{"The operator loop's rate on the built-in scenes (nearest-obstacle query included)"};
  double seconds = 2.0;
  app.add_option("--seconds", seconds, "Time per scene (default 2)")->check(CLI::PositiveNumber);
  if (const auto code = bench::parse_arguments(app, argc, argv, "tandem-operator-loop"))
    return *code;

  std::printf(
      "| scene | obstacles | states/s | mean per state (us) | states with a contact frame |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: |\n");
  for (const tandem::BuiltinScene& scene : tandem::builtin_scenes()) {
    const tandem::Problem problem = tandem::load_problem(std::string(scene.name));
    if (problem.guide.empty())
      continue;
    tandem::CollisionChecker checker(problem.scene);
    const bench::GuideWalk walk = bench::walk_guide(problem, checker, seconds);
    const auto states = static_cast<double>(walk.states);
    std::printf("| %s | %zu | %.0f | %.1f | %.0f%% |\n", problem.name.c_str(),
                problem.scene.obstacles.size(), states / walk.seconds, 1e6 * walk.seconds / states,
                100.0 * static_cast<double>(walk.framed) / states);
  }
  return 0;
}
