#pragma once
// What the planner moves and what it must avoid.

#include <string>
#include <vector>

#include "tandem/scene/geometry.hpp"

namespace tandem {

struct Scene {
  Body object;                  ///< the moving part; its parts are posed in the object frame
  std::vector<Body> obstacles;  ///< static, named; their parts are posed in the world frame
};

}  // namespace tandem
