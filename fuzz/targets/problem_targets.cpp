// The problem files: an OMPL.app .cfg and a tandem scenario, each with the files it names (meshes
// of every format assimp reads, URDF), through load_problem as the command line reads them.

#include "fuzz_target.hpp"
#include "scratch_folder.hpp"
#include "tandem/core/error.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem::fuzz {
namespace {

bool load_bundle(std::string_view input, std::string_view main_name) {
  const std::filesystem::path file = write_bundle(input, main_name);
  try {
    (void)load_problem(file.string());
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

bool cfg(std::string_view input) {
  return load_bundle(input, "problem.cfg");
}

bool scenario(std::string_view input) {
  return load_bundle(input, "scenario.toml");
}

}  // namespace tandem::fuzz
