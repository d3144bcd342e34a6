#pragma once
// Nearest-neighbour search over a growing set of configurations, under the space's metric.
//
// The index never owns the configurations: it holds ids into a std::vector<Config> owned by the
// caller (a planner's tree), which must outlive the index and may only grow (ids stay valid;
// reallocation is fine because the index reads through the vector, not through pointers to its
// elements). Threading: not thread-safe; queries are const but must not run concurrently with
// add().

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "tandem/space/se3_space.hpp"

namespace tandem {

using NodeId = std::uint32_t;

class NearestNeighbors {
 public:
  NearestNeighbors(const SE3Space& space, const std::vector<Config>& points)
      : space_(space), points_(points) {}
  virtual ~NearestNeighbors() = default;
  NearestNeighbors(const NearestNeighbors&) = delete;
  NearestNeighbors& operator=(const NearestNeighbors&) = delete;

  /// Adds points()[id] to the index.
  virtual void add(NodeId id) = 0;
  virtual std::size_t size() const = 0;
  virtual void clear() = 0;

  /// The nearest indexed point to q (ties: any). Requires size() > 0.
  virtual NodeId nearest(const Config& q) const = 0;

  /// The k nearest indexed points to q, nearest first (fewer if fewer are indexed).
  virtual void k_nearest(const Config& q, std::size_t k, std::vector<NodeId>& out) const = 0;

  const SE3Space& space() const { return space_; }
  const std::vector<Config>& points() const { return points_; }

 protected:
  const SE3Space& space_;
  const std::vector<Config>& points_;
};

/// Which implementation: "kdtree" (default) or "linear" (brute force, for tests and tiny sets).
std::unique_ptr<NearestNeighbors> make_nearest_neighbors(std::string_view kind,
                                                         const SE3Space& space,
                                                         const std::vector<Config>& points);

}  // namespace tandem
