#pragma once
// A dynamic, bucketed k-d tree over the translation of configurations, searched exactly under the
// full SE(3) metric.
//
// Cells split on translation coordinates only. The lower bound used for pruning is the weighted
// Euclidean distance from the query's translation to the cell, which never exceeds the metric
// w_t |dt| + w_r angle (the rotation term is >= 0), so the search is exact for any rotation weight.
// Points are inserted one at a time (RRT trees grow this way); a leaf splits at the median of its
// widest translation axis when it holds more than kBucketSize points. RRT-Connect adds long runs of
// points along a line, which would make a plain k-d tree a list; the tree stays balanced as a
// scapegoat tree does: when an insertion lands too deep, the highest unbalanced subtree on its path
// is rebuilt at medians (amortised O(log n) per insertion).

#include <array>

#include "tandem/nn/nearest_neighbors.hpp"

namespace tandem {

class KdTreeNearestNeighbors final : public NearestNeighbors {
 public:
  static constexpr std::size_t kBucketSize = 16;

  KdTreeNearestNeighbors(const SE3Space& space, const std::vector<Config>& points);

  void add(NodeId id) override;
  std::size_t size() const override { return size_; }
  void clear() override;
  NodeId nearest(const Config& q) const override;
  void k_nearest(const Config& q, std::size_t k, std::vector<NodeId>& out) const override;

 private:
  static constexpr double kAlpha =
      0.75;  ///< a child may hold at most this share of its parent's points

  struct Node {
    int axis = -1;       ///< -1 for a leaf
    double split = 0.0;  ///< points with t[axis] < split go left
    std::uint32_t left = 0, right = 0;
    std::uint32_t count = 0;     ///< points in the subtree
    std::vector<NodeId> bucket;  ///< leaf only
  };

  std::uint32_t new_node();
  void split_leaf(std::uint32_t leaf);
  /// Rebuilds the subtree at `root` balanced, reusing its node slots.
  void rebuild(std::uint32_t root);
  void collect(std::uint32_t node, std::vector<NodeId>& ids);
  void build(std::uint32_t node, std::vector<NodeId>::iterator first,
             std::vector<NodeId>::iterator last);
  template <class Visit>
  void search(std::uint32_t node, const Config& q, std::array<double, 3>& offset, double offset2,
              Visit& visit) const;

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> free_;  ///< node slots released by rebuilds
  std::vector<std::uint32_t> path_;  ///< scratch for add()
  std::size_t size_ = 0;
};

}  // namespace tandem
