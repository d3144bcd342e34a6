#pragma once
// The scene a CAD assembly gives: the part that moves, and the rest of the assembly as obstacles.
//
// Every leaf part with triangles is an obstacle named by its path in the assembly tree
// ("housing/lid-1/lid"), in its colour, posed by its placement. The part named to move (if any)
// is the object instead: its triangles in its own frame, and the configuration where it sits in
// the assembly.

#include <optional>
#include <string>

#include "tandem/scene/cad_loader.hpp"
#include "tandem/scene/scene.hpp"
#include "tandem/space/config.hpp"

namespace tandem {

struct CadScene {
  std::vector<Body> obstacles;
  std::optional<Body> object;  ///< the part that moves, in its own frame
  std::optional<Config> seat;  ///< where it sits in the assembly
};

/// `part`: the name or path of the part that moves, or empty for none. `source` names the file
/// (or option) for the error when no part, or several, have that name.
CadScene cad_scene(const CadAssembly& assembly, const std::string& part, const std::string& file,
                   const std::string& source);

}  // namespace tandem
