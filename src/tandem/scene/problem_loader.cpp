#include "tandem/scene/problem_loader.hpp"

#include <algorithm>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/scene/builtin_scenes.hpp"
#include "tandem/scene/ompl_app_problem.hpp"
#include "tandem/scene/scenario_file.hpp"

namespace tandem {

Problem load_problem(const std::string& spec, const ProblemLoadOptions& options) {
  check_file_name(spec);
  std::error_code ec;
  const std::filesystem::path path(spec);
  if (std::filesystem::exists(path, ec)) {
    if (std::filesystem::is_directory(path, ec))
      throw InputError(spec, "is a folder, not a problem file");
    const std::string ext = lower_extension(path);
    if (is_cad_file(path))
      return take_out_problem(path, options.take_out);
    if (!options.take_out.part.empty())
      throw InputError("--part", "takes a part out of a STEP or IGES file, not of '" + spec + "'");
    if (ext == ".cfg")
      return load_ompl_app_problem(path);
    if (ext == ".toml") {
      FileAccess access;
      access.roots.push_back(std::filesystem::absolute(path).parent_path());
      for (const auto& d : options.allowed_dirs)
        access.roots.push_back(std::filesystem::absolute(d));
      return load_scenario_file(path, access);
    }
    throw InputError(spec,
                     "unknown problem format '" + ext +
                         "' (expected an OMPL.app .cfg, a tandem .toml scenario, or a STEP or IGES "
                         "assembly with --part)");
  }
  if (!options.take_out.part.empty())
    throw InputError("--part", "takes a part out of a STEP or IGES file, not of '" + spec + "'");
  for (const auto& scene : builtin_scenes()) {
    if (scene.name == spec)
      return parse_scenario(scene.text, "built-in scene '" + spec + "'", {}, {});
  }
  std::string names;
  for (const auto& scene : builtin_scenes())
    names += (names.empty() ? "" : ", ") + std::string(scene.name);
  throw InputError(
      spec, "no such file, and no built-in scene of that name (built-in scenes: " + names + ")");
}

}  // namespace tandem
