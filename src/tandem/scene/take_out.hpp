#pragma once
// "Take this part out": the problem a CAD assembly and the name of one of its parts make.
//
// The named part moves; the rest of the assembly is the environment (cad_scene.hpp). The start is
// where the part sits, its surface moved inward by the seating tolerance so that it may slide out
// of the seat it touches. The goal is a region: the whole part outside the assembly's bounding box
// grown by a margin (goal_region.hpp). The planners aim at one configuration of the region: the
// part moved straight out, along the one of the six axis directions that gets it there the
// soonest, keeping its orientation; as the region's outside of a box is connected, any of its
// configurations leads to any other, and a solution ends where it first enters the region.
//
// The workspace: the grown box and, around it, room for the part to turn (its radius about its
// centre). A radian of rotation weighs the part's radius (as far as its farthest point moves), so
// the metric does not depend on the unit; the resolution is tandem's default.

#include <filesystem>
#include <string>

#include "tandem/scene/cad_loader.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

struct TakeOutOptions {
  std::string part;              ///< its name or path in the assembly tree
  double margin = 0.0;           ///< metres; 0: 5% of the assembly's bounding-box diagonal
  double seat_tolerance = -1.0;  ///< metres; negative: twice the linear deflection
  CadOptions cad;
};

/// Throws InputError naming the file or option and the fault.
Problem take_out_problem(const std::filesystem::path& file, const TakeOutOptions& options);

/// The whole assembly, for choosing the part to take out (the viewer shows it): every part an
/// obstacle, an object with no geometry, bounds around the assembly, start and goal at its centre.
/// `options.part` is ignored. Throws InputError naming the file.
Problem assembly_problem(const std::filesystem::path& file, const TakeOutOptions& options);

}  // namespace tandem
