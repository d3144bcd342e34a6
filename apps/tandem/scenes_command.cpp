// tandem scenes: the scenes shipped inside tandem.

#include <iostream>

#include "commands.hpp"
#include "tandem/core/error.hpp"
#include "tandem/scene/builtin_scenes.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem::cli {

Command add_scenes_command(CLI::App& app) {
  auto name = std::make_shared<std::string>();
  app.add_option("NAME", *name, "Print this scene's scenario file (a starting point for your own)");
  return [name]() -> int {
    if (name->empty()) {
      for (const auto& scene : builtin_scenes()) {
        const Problem p = load_problem(std::string(scene.name));
        std::cout << scene.name << "\t" << p.scene.obstacles.size() << " obstacles\n";
      }
      return 0;
    }
    for (const auto& scene : builtin_scenes()) {
      if (scene.name == *name) {
        std::cout << scene.text;
        return 0;
      }
    }
    throw InputError(*name, "no built-in scene of that name (see 'tandem scenes')");
  };
}

}  // namespace tandem::cli
