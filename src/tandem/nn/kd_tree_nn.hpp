#pragma once
// A dynamic, bucketed k-d tree over the translation of configurations, searched exactly under the
// full SE(3) metric.
//
// Nodes split on translation coordinates only, and each keeps the bounding box of the points below
// it. The lower bound used for pruning is the weighted Euclidean distance from the query's
// translation to that box, which never exceeds the metric w_t |dt| + w_r angle (the rotation term
// is >= 0), so the search is exact for any rotation weight; tight boxes (rather than cells) keep it
// fast when the tree is clustered and the query far away, as RRT queries often are. In a leaf, a
// point is measured exactly (an atan2) only when a cheap lower bound of its distance is below the
// current bound: w_t |dt| first, then w_t |dt| + w_r 2 |a - b| (SE3Space::rotation_lower_bound),
// which is within 10% of the rotation term at any angle. A point skipped is strictly farther than
// the bound, so the search returns what it would without the bound, the same node on ties.
//
// Points are inserted one at a time (RRT trees grow this way); a leaf splits at the median of its
// widest translation axis when it holds more than kBucketSize points. RRT-Connect adds long runs of
// points along a line, which would make a plain k-d tree a list; the tree stays balanced as a
// scapegoat tree does: when an insertion lands too deep, the highest unbalanced subtree on its path
// is rebuilt at medians (amortised O(log n) per insertion).

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
  /// A child may hold at most this share of its parent's points before the subtree is rebuilt.
  static constexpr double kAlpha = 0.75;

  /// A point in a leaf, with its translation and rotation inline so that a leaf scan reads
  /// contiguous memory.
  struct Entry {
    Eigen::Vector3d t;
    Eigen::Quaterniond q;
    NodeId id;
  };

  struct Node {
    int axis = -1;       ///< -1 for a leaf
    double split = 0.0;  ///< points with t[axis] < split go left
    std::uint32_t left = 0, right = 0;
    std::uint32_t count = 0;  ///< points in the subtree
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    std::vector<Entry> bucket;  ///< leaf only

    /// Squared distance from p to the box of the subtree's points.
    double box_distance2(const Eigen::Vector3d& p) const {
      return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).squaredNorm();
    }
  };

  std::uint32_t new_node();
  void split_leaf(std::uint32_t leaf);
  /// Rebuilds the subtree at `root` balanced, reusing its node slots.
  void rebuild(std::uint32_t root);
  void collect(std::uint32_t node, std::vector<NodeId>& ids);
  void build(std::uint32_t node, std::vector<NodeId>::iterator first,
             std::vector<NodeId>::iterator last);
  template <class Visit>
  void scan_leaf(const Node& leaf, const Config& q, Visit& visit) const;
  template <class Visit>
  void search(std::uint32_t node, const Config& q, Visit& visit) const;

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> free_;  ///< node slots released by rebuilds
  std::vector<std::uint32_t> path_;  ///< scratch for add()
  std::size_t size_ = 0;
};

}  // namespace tandem
