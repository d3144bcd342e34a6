#pragma once
// The scene a CAD assembly gives: the part that moves, and the rest of the assembly as obstacles.
//
// Every leaf part with triangles is an obstacle named by its path in the assembly tree
// ("housing/lid-1/lid"), in its colour, posed by its placement. The part named to move (if any)
// is the object instead, and the configuration where it sits in the assembly its seat. The
// object's frame is the part's own frame moved to the centre of the part's bounding box (in that
// frame), so that a configuration turns the part about its middle. Its surface is moved inward by
// the seating tolerance (mesh_inset.hpp), so that it can leave the seat it touches.

#include <optional>
#include <string>

#include "tandem/scene/cad_loader.hpp"
#include "tandem/scene/scene.hpp"
#include "tandem/space/config.hpp"

namespace tandem {

struct CadScene {
  std::vector<Body> obstacles;
  std::optional<Body> object;  ///< the part that moves, in the object frame (below)
  std::optional<Config> seat;  ///< where it sits in the assembly
  /// The object frame in the part's own frame: a translation to its bounding box's centre.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double seat_tolerance = 0.0;  ///< metres the object's surface was moved inward
};

/// The default seating tolerance: twice the tessellation's linear deflection.
double default_seat_tolerance(const CadAssembly& assembly);

/// `part`: the name or path of the part that moves, or empty for none. `source` names the file
/// (or option) for the error when no part, or several, have that name. `seat_tolerance`: metres,
/// 0 for none.
CadScene cad_scene(const CadAssembly& assembly, const std::string& part, const std::string& file,
                   const std::string& source, double seat_tolerance);

}  // namespace tandem
