#pragma once
// A dynamic, bucketed k-d tree over the seven numbers of a configuration (translation and
// quaternion), searched exactly under the full SE(3) metric.
//
// Each point is keyed by its translation and its quaternion's coefficients, the quaternion taken
// on the hemisphere w >= 0 (q and -q are one rotation). Nodes split on any of the seven keys, the
// widest under the metric's weights, and each keeps the bounding box of the keys below it. The
// lower bound used for pruning a box is
//   w_t |dt| + w_r 2 min(|q - box|, |-q - box|)
// with dt the query's translation to the box and |q - box| the distance of the query's quaternion
// to the box in R^4: the chord |q - p| to a unit quaternion p is 2 sin(theta / 4) for a rotation
// of theta, so twice it never exceeds theta (SE3Space::rotation_lower_bound), and it is within
// 10% of it. Tight boxes (rather than cells) keep the search fast when the tree is clustered and
// the query far away, as RRT queries often are. In a leaf, a point is measured exactly (an atan2)
// only when the same bound for the point itself is below the current best.
//
// Ties are broken by the smaller id, as a linear scan in insertion order does, so the answer does
// not depend on the tree's shape; a point is skipped only when its bound exceeds the best.
//
// Points are inserted one at a time (RRT trees grow this way); a leaf splits at the median of its
// widest key when it holds more than kBucketSize points. RRT-Connect adds long runs of points
// along a line, which would make a plain k-d tree a list; the tree stays balanced as a scapegoat
// tree does: when an insertion lands too deep, the highest unbalanced subtree on its path is
// rebuilt at medians (amortised O(log n) per insertion).
//
// Insertions and those partial rebuilds scatter nodes and leaf buckets over memory, and at a
// million points the search waits on those reads more than it computes. Each time the tree has
// grown by kCompactionGrowth it is rebuilt whole into fresh storage: nodes depth-first, both
// children of a node side by side, buckets allocated in the same order (amortised O(log n) per
// insertion too; the rebuild holds a copy of the entries, 64 bytes a point, while it runs).

#include <limits>

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
  /// The whole tree is rebuilt when it reaches kFirstCompaction points and each time it has grown
  /// by this factor since.
  static constexpr double kCompactionGrowth = 2.0;
  static constexpr std::size_t kFirstCompaction = 4096;

  /// A point's key: translation, then the quaternion's coefficients (x, y, z, w) with w >= 0.
  using Key = Eigen::Matrix<double, 7, 1>;

  /// A point in a leaf, with its key inline so that a leaf scan reads contiguous memory.
  struct Entry {
    Key key;
    NodeId id;
  };

  struct Node {
    int axis = -1;       ///< -1 for a leaf
    double split = 0.0;  ///< points with key[axis] < split go left
    std::uint32_t left = 0, right = 0;
    std::uint32_t count = 0;  ///< points in the subtree
    Key lo = Key::Constant(std::numeric_limits<double>::infinity());
    Key hi = -Key::Constant(std::numeric_limits<double>::infinity());
    std::vector<Entry> bucket;  ///< leaf only
  };

  /// The query as the searches use it: its key and its quaternion's opposite.
  struct Query {
    const Config& q;
    Key key;
    Eigen::Vector4d minus_q;
  };

  /// Twice the chord bounds the rotation angle (see SE3Space::rotation_lower_bound).
  static constexpr double kChordWeight = SE3Space::kChordBound;

  Key key(const Config& c) const;
  Query query(const Config& q) const;
  /// Lower bound of the distance from the query to any point whose key is in [lo, hi].
  double box_bound(const Query& query, const Key& lo, const Key& hi) const;
  /// Lower bound of the distance from the query to the point with this key, SE3Space's bound of
  /// the rotation term (the box bound of a one-point box, but cheaper).
  double point_bound(const Query& query, const Key& key) const;

  std::uint32_t new_node();
  void split_leaf(std::uint32_t leaf);
  /// Rebuilds the subtree at `root` balanced, reusing its node slots (all of the tree, in fresh
  /// slots, for the root).
  void rebuild(std::uint32_t root);
  /// Copies the entries below `node` to `entries` and releases its descendants' slots.
  void collect(std::uint32_t node, std::vector<Entry>& entries);
  void build(std::uint32_t node, std::vector<Entry>::iterator first,
             std::vector<Entry>::iterator last);
  template <class Visit>
  void scan_leaf(const Node& leaf, const Query& query, Visit& visit) const;
  template <class Visit>
  void search(std::uint32_t node, const Query& query, Visit& visit) const;
  /// The key's weight under the metric, for choosing the widest axis to split.
  Key axis_weights() const;

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> free_;  ///< node slots released by rebuilds
  std::vector<std::uint32_t> path_;  ///< scratch for add()
  std::size_t size_ = 0;
  std::size_t next_compaction_ = kFirstCompaction;
};

}  // namespace tandem
