#include "tandem/scene/take_out.hpp"

#include <cmath>
#include <limits>

#include "tandem/core/error.hpp"
#include "tandem/scene/cad_scene.hpp"

namespace tandem {
namespace {

/// The seat moved straight out along the axis direction that leaves the region's box soonest.
Config nearest_exit(const GoalRegion& region, const Config& seat) {
  const auto [lo, hi] = region.posed_box(seat);
  const double clear = 0.01 * region.margin;  // strictly outside
  Config best = seat;
  double shortest = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      const double move =
          sign > 0 ? region.max[axis] - lo[axis] + clear : hi[axis] - region.min[axis] + clear;
      if (move < shortest) {
        shortest = move;
        best = seat;
        best.t[axis] += sign * move;
      }
    }
  }
  return best;
}

void check(const TakeOutOptions& o) {
  if (o.part.empty())
    throw InputError("--part", "name the part to take out ('tandem parts FILE' lists them)");
  if (!std::isfinite(o.margin) || o.margin < 0.0)
    throw InputError("--margin", "must be a non-negative number of metres");
  if (!std::isfinite(o.seat_tolerance))
    throw InputError("--seat-tolerance", "must be a number of metres");
}

}  // namespace

Problem take_out_problem(const std::filesystem::path& file, const TakeOutOptions& options) {
  check(options);
  const CadAssembly assembly = load_cad(file, options.cad);
  const double seat_tolerance =
      options.seat_tolerance >= 0.0 ? options.seat_tolerance : default_seat_tolerance(assembly);
  CadScene cad = cad_scene(assembly, options.part, file.string(), "--part", seat_tolerance);
  const auto [lo, hi] = assembly.bounding_box();
  GoalRegion region;
  region.margin = options.margin > 0.0 ? options.margin : 0.05 * (hi - lo).norm();
  region.min = lo.array() - region.margin;
  region.max = hi.array() + region.margin;
  const TriangleMesh& mesh = *std::get<MeshShape>(cad.object->parts.front().geometry).mesh;
  region.points = mesh.vertices;
  double radius = 0.0;
  for (const auto& v : mesh.vertices)
    radius = std::max(radius, v.norm());
  Bounds bounds;
  bounds.min = region.min.array() - 2.0 * radius;
  bounds.max = region.max.array() + 2.0 * radius;
  // A radian of turn weighs as much as the part's farthest point moves by it.
  const SE3Space space(SpaceKind::se3, bounds, MetricWeights{1.0, radius});
  Scene scene{std::move(*cad.object), std::move(cad.obstacles)};
  const Config goal = nearest_exit(region, *cad.seat);
  const std::string name = "take " + options.part + " out of " + file.stem().string();
  return Problem{name, file.string(),    std::move(scene), space, *cad.seat, goal, {},
                 {},   std::move(region)};
}

Problem assembly_problem(const std::filesystem::path& file, const TakeOutOptions& options) {
  const CadAssembly assembly = load_cad(file, options.cad);
  CadScene cad = cad_scene(assembly, "", file.string(), "--part", 0.0);
  const auto [lo, hi] = assembly.bounding_box();
  const double grow = 0.05 * (hi - lo).norm();
  Bounds bounds;
  bounds.min = lo.array() - grow;
  bounds.max = hi.array() + grow;
  Config centre;
  centre.t = (lo + hi) / 2;
  Scene scene{Body{"(no part chosen)", {}, {}}, std::move(cad.obstacles)};
  return Problem{"choose a part of " + file.stem().string(),
                 file.string(),
                 std::move(scene),
                 SE3Space(SpaceKind::se3, bounds),
                 centre,
                 centre,
                 {},
                 {},
                 std::nullopt};
}

}  // namespace tandem
