#include "tandem/nn/kd_tree_nn.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>

#include "tandem/nn/linear_nn.hpp"

namespace tandem {

KdTreeNearestNeighbors::KdTreeNearestNeighbors(const SE3Space& space,
                                               const std::vector<Config>& points)
    : NearestNeighbors(space, points) {
  clear();
}

void KdTreeNearestNeighbors::clear() {
  nodes_.assign(1, Node{});
  free_.clear();
  size_ = 0;
}

std::uint32_t KdTreeNearestNeighbors::new_node() {
  if (!free_.empty()) {
    const std::uint32_t n = free_.back();
    free_.pop_back();
    nodes_[n] = Node{};
    return n;
  }
  nodes_.emplace_back();
  return static_cast<std::uint32_t>(nodes_.size() - 1);
}

void KdTreeNearestNeighbors::add(NodeId id) {
  const Eigen::Vector3d& t = points_[id].t;
  path_.clear();
  std::uint32_t n = 0;
  for (;;) {
    path_.push_back(n);
    Node& node = nodes_[n];
    ++node.count;
    node.lo = node.lo.cwiseMin(t);
    node.hi = node.hi.cwiseMax(t);
    if (node.axis < 0)
      break;
    n = t[node.axis] < node.split ? node.left : node.right;
  }
  nodes_[n].bucket.push_back({t, points_[id].q, id});
  ++size_;
  if (nodes_[n].bucket.size() > kBucketSize)
    split_leaf(n);

  // Depth allowed for a kAlpha-balanced tree of this size, plus slack for the bucket level.
  const double leaves = static_cast<double>(size_) / static_cast<double>(kBucketSize) + 1.0;
  const auto allowed = static_cast<std::size_t>(std::log(leaves) / std::log(1.0 / kAlpha)) + 2;
  if (path_.size() <= allowed)
    return;
  for (std::size_t i = 0; i + 1 < path_.size(); ++i) {
    const Node& a = nodes_[path_[i]];
    const std::uint32_t heavier = std::max(nodes_[a.left].count, nodes_[a.right].count);
    if (static_cast<double>(heavier) > kAlpha * static_cast<double>(a.count)) {
      rebuild(path_[i]);
      return;
    }
  }
}

void KdTreeNearestNeighbors::collect(std::uint32_t node, std::vector<NodeId>& ids) {
  Node& n = nodes_[node];
  if (n.axis < 0) {
    for (const Entry& e : n.bucket)
      ids.push_back(e.id);
    return;
  }
  collect(n.left, ids);
  collect(n.right, ids);
  free_.push_back(n.left);
  free_.push_back(n.right);
}

void KdTreeNearestNeighbors::rebuild(std::uint32_t root) {
  std::vector<NodeId> ids;
  ids.reserve(nodes_[root].count);
  collect(root, ids);
  nodes_[root] = Node{};
  build(root, ids.begin(), ids.end());
}

void KdTreeNearestNeighbors::build(std::uint32_t node, std::vector<NodeId>::iterator first,
                                   std::vector<NodeId>::iterator last) {
  const auto count = static_cast<std::size_t>(last - first);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (auto it = first; it != last; ++it) {
    lo = lo.cwiseMin(points_[*it].t);
    hi = hi.cwiseMax(points_[*it].t);
  }
  nodes_[node].count = static_cast<std::uint32_t>(count);
  nodes_[node].lo = lo;
  nodes_[node].hi = hi;
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  if (count <= kBucketSize || !(hi[axis] > lo[axis])) {
    // A leaf (also when all points share one position: it then just grows).
    nodes_[node].axis = -1;
    nodes_[node].bucket.clear();
    for (auto it = first; it != last; ++it)
      nodes_[node].bucket.push_back({points_[*it].t, points_[*it].q, *it});
    return;
  }
  auto mid = first + static_cast<std::ptrdiff_t>(count / 2);
  std::nth_element(first, mid, last,
                   [&](NodeId a, NodeId b) { return points_[a].t[axis] < points_[b].t[axis]; });
  double split = points_[*mid].t[axis];
  if (split <= lo[axis])
    split = std::nextafter(lo[axis], hi[axis]);
  // Points at the split value go right; both sides are non-empty since lo < split <= hi.
  mid = std::partition(first, last, [&](NodeId a) { return points_[a].t[axis] < split; });
  const std::uint32_t l = new_node();
  const std::uint32_t r = new_node();
  nodes_[node].axis = axis;
  nodes_[node].split = split;
  nodes_[node].left = l;
  nodes_[node].right = r;
  nodes_[node].bucket.clear();
  nodes_[node].bucket.shrink_to_fit();
  build(l, first, mid);
  build(r, mid, last);
}

void KdTreeNearestNeighbors::split_leaf(std::uint32_t leaf) {
  std::vector<NodeId> ids;
  for (const Entry& e : nodes_[leaf].bucket)
    ids.push_back(e.id);
  build(leaf, ids.begin(), ids.end());
}

// A point is measured only when its lower bounds are below the current bound: the translation
// term alone (no square root), then with the rotation term's chord bound (no atan2).
template <class Visit>
void KdTreeNearestNeighbors::scan_leaf(const Node& leaf, const Config& q, Visit& visit) const {
  const double wt = space_.weights().translation;
  const double wr = space_.weights().rotation;
  for (const Entry& e : leaf.bucket) {
    const double bound = visit.bound();
    const double dt2 = (q.t - e.t).squaredNorm();
    if (wt * wt * dt2 >= bound * bound)
      continue;
    if (wt * std::sqrt(dt2) + wr * SE3Space::rotation_lower_bound(q.q, e.q) >= bound)
      continue;
    visit.consider(e.id, space_.distance(q, Config{e.t, e.q}));
  }
}

// Depth-first, the child whose box is nearer first; a child is skipped when the weighted distance
// to its box reaches the current bound.
template <class Visit>
void KdTreeNearestNeighbors::search(std::uint32_t n, const Config& q, Visit& visit) const {
  const Node& node = nodes_[n];
  const double wt2 = space_.weights().translation * space_.weights().translation;
  if (node.axis < 0) {
    scan_leaf(node, q, visit);
    return;
  }
  const double dl = wt2 * nodes_[node.left].box_distance2(q.t);
  const double dr = wt2 * nodes_[node.right].box_distance2(q.t);
  const bool left_first = dl <= dr;
  const std::uint32_t first = left_first ? node.left : node.right;
  const std::uint32_t second = left_first ? node.right : node.left;
  const double d_first = left_first ? dl : dr;
  const double d_second = left_first ? dr : dl;
  double bound = visit.bound();
  if (d_first < bound * bound)
    search(first, q, visit);
  bound = visit.bound();
  if (d_second < bound * bound)
    search(second, q, visit);
}

NodeId KdTreeNearestNeighbors::nearest(const Config& q) const {
  if (size_ == 0)
    throw std::logic_error("nearest() on an empty index");
  struct Best {
    double d = std::numeric_limits<double>::infinity();
    NodeId id = 0;
    double bound() const { return d; }
    void consider(NodeId i, double di) {
      if (di < d) {
        d = di;
        id = i;
      }
    }
  } best;
  search(0, q, best);
  return best.id;
}

void KdTreeNearestNeighbors::k_nearest(const Config& q, std::size_t k,
                                       std::vector<NodeId>& out) const {
  out.clear();
  if (k == 0 || size_ == 0)
    return;
  struct KBest {
    std::size_t k;
    std::priority_queue<std::pair<double, NodeId>> heap;  // max-heap: the worst of the k on top
    double bound() const {
      return heap.size() < k ? std::numeric_limits<double>::infinity() : heap.top().first;
    }
    void consider(NodeId i, double di) {
      if (heap.size() < k) {
        heap.emplace(di, i);
      } else if (di < heap.top().first) {
        heap.pop();
        heap.emplace(di, i);
      }
    }
  } best{k, {}};
  search(0, q, best);
  out.resize(best.heap.size());
  for (std::size_t i = out.size(); i-- > 0;) {
    out[i] = best.heap.top().second;
    best.heap.pop();
  }
}

std::unique_ptr<NearestNeighbors> make_nearest_neighbors(std::string_view kind,
                                                         const SE3Space& space,
                                                         const std::vector<Config>& points) {
  if (kind == "linear")
    return std::make_unique<LinearNearestNeighbors>(space, points);
  if (kind == "kdtree" || kind.empty())
    return std::make_unique<KdTreeNearestNeighbors>(space, points);
  throw std::invalid_argument("unknown nearest-neighbour index '" + std::string(kind) + "'");
}

}  // namespace tandem
