#include "tandem/io/clearance_json.hpp"

namespace tandem {
namespace {

nlohmann::json point(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

}  // namespace

nlohmann::json clearance_json(const PathClearance& c, const CollisionChecker& checker) {
  nlohmann::json states = nlohmann::json::array(), segments = nlohmann::json::array();
  for (const auto& s : c.states)
    states.push_back({{"distance", s.distance},
                      {"obstacle", checker.obstacle_name(s.obstacle)},
                      {"point_on_object", point(s.point_on_object)},
                      {"point_on_obstacle", point(s.point_on_obstacle)}});
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    const SegmentClearance& s = c.segments[i];
    segments.push_back({{"from", i},
                        {"to", i + 1},
                        {"lower", s.lower},
                        {"found", s.found},
                        {"at", s.at},
                        {"obstacle", checker.obstacle_name(s.obstacle)},
                        {"queries", s.queries}});
  }
  return {{"min_clearance", c.lower()},
          {"accuracy", c.accuracy},
          {"floor", c.floor},
          {"states", states},
          {"segments", segments}};
}

}  // namespace tandem
