#pragma once
// The JSON form of a path's clearance (tandem clearance --json, and the viewer's /api/clearance):
// {min_clearance, accuracy, floor, states: [{distance, obstacle, point_on_object,
// point_on_obstacle}], segments: [{from, to, lower, found, at, obstacle, queries}]}, obstacles by
// name.

#include <nlohmann/json.hpp>

#include "tandem/planning/path_clearance.hpp"

namespace tandem {

nlohmann::json clearance_json(const PathClearance& clearance, const CollisionChecker& checker);

}  // namespace tandem
