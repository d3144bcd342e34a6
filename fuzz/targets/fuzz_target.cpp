#include "fuzz_target.hpp"

#include <array>

namespace tandem::fuzz {

std::span<const Target> targets() {
  static constexpr std::array<Target, 8> kTargets{{
      {"cfg", cfg, "an OMPL.app problem (.cfg) with the meshes it names (a bundle)"},
      {"scenario", scenario, "a scenario (.toml) with the meshes and URDF it names (a bundle)"},
      {"experiment", experiment, "an experiment (.toml)"},
      {"path", path, "a path file (OMPL's path format)"},
      {"trace", trace, "an operator trace"},
      {"journal", journal, "a session journal, and its replay on the built-in scene 'maze'",
       prepare_journal},
      {"protocol", protocol, "a viewer message (the WebSocket's text frames)"},
      {"step", step, "a STEP file (or IGES, when it does not start as STEP does)"},
  }};
  return kTargets;
}

const Target* find_target(std::string_view name) {
  for (const Target& t : targets()) {
    if (t.name == name)
      return &t;
  }
  return nullptr;
}

}  // namespace tandem::fuzz
