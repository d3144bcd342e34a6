#pragma once
// A generated scene family for scaling measurements: N boxes scattered in a cube whose size grows
// with N so that the obstacles fill the same share of it (the free volume per part stays
// constant), and a 0.6 m bar to move. Its problem is the same at every N: from one side of the
// cube's centre to the other, 2 m apart, within a fixed 3 m region around the centre (the
// planner's bounds). With the default box size the cube is that region at N = 10 and grows from
// there, so the region holds about as many boxes at every N: only the number of parts around it
// changes.

#include <cstddef>
#include <cstdint>

#include "tandem/scene/problem.hpp"

namespace tandem {

struct BoxFieldOptions {
  std::size_t parts = 100;  ///< N, the number of boxes (obstacles)
  std::uint64_t seed = 1;   ///< where they lie and how large they are
  double fill = 0.02;       ///< the share of the cube's volume the boxes take
  double box_size = 0.4;    ///< mean edge of a box (m); each edge is 0.5 to 1.5 times it
};

/// The problem "boxes-N": the boxes as N obstacles ("box 0", ...), none within 0.4 m of the start
/// or the goal. Throws InputError for no parts or a fill outside (0, 0.5].
Problem box_field_problem(const BoxFieldOptions& options);

}  // namespace tandem
