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

KdTreeNearestNeighbors::Key KdTreeNearestNeighbors::key(const Config& c) const {
  Key k;
  k.head<3>() = c.t;
  k.tail<4>() = c.q.w() < 0.0 ? Eigen::Vector4d(-c.q.coeffs()) : Eigen::Vector4d(c.q.coeffs());
  return k;
}

KdTreeNearestNeighbors::Key KdTreeNearestNeighbors::axis_weights() const {
  Key w;
  w.head<3>().setConstant(space_.weights().translation);
  w.tail<4>().setConstant(kChordWeight * space_.weights().rotation);
  return w;
}

double KdTreeNearestNeighbors::box_bound(const Query& query, const Key& lo, const Key& hi) const {
  const Key& k = query.key;
  const double dt =
      (lo.head<3>() - k.head<3>()).cwiseMax(k.head<3>() - hi.head<3>()).cwiseMax(0.0).norm();
  const auto to_box = [&](const Eigen::Vector4d& v) {
    return (lo.tail<4>() - v).cwiseMax(v - hi.tail<4>()).cwiseMax(0.0).norm();
  };
  const double chord = std::min(to_box(k.tail<4>()), to_box(query.minus_q));
  return space_.weights().translation * dt + space_.weights().rotation * kChordWeight * chord;
}

double KdTreeNearestNeighbors::point_bound(const Query& query, const Key& key) const {
  const Eigen::Map<const Eigen::Quaterniond> q(key.tail<4>().data());
  return space_.weights().translation * (query.key.head<3>() - key.head<3>()).norm() +
         space_.weights().rotation * SE3Space::rotation_lower_bound(query.q.q, q);
}

void KdTreeNearestNeighbors::clear() {
  nodes_.assign(1, Node{});
  free_.clear();
  size_ = 0;
  next_compaction_ = kFirstCompaction;
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
  const Key k = key(points_[id]);
  path_.clear();
  std::uint32_t n = 0;
  for (;;) {
    path_.push_back(n);
    Node& node = nodes_[n];
    ++node.count;
    node.lo = node.lo.cwiseMin(k);
    node.hi = node.hi.cwiseMax(k);
    if (node.axis < 0)
      break;
    n = k[node.axis] < node.split ? node.left : node.right;
  }
  nodes_[n].bucket.push_back({k, id});
  ++size_;
  if (nodes_[n].bucket.size() > kBucketSize)
    split_leaf(n);
  if (size_ >= next_compaction_) {
    next_compaction_ = static_cast<std::size_t>(kCompactionGrowth * static_cast<double>(size_));
    rebuild(0);
    return;
  }

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

void KdTreeNearestNeighbors::collect(std::uint32_t node, std::vector<Entry>& entries) {
  Node& n = nodes_[node];
  if (n.axis < 0) {
    entries.insert(entries.end(), n.bucket.begin(), n.bucket.end());
    return;
  }
  collect(n.left, entries);
  collect(n.right, entries);
  free_.push_back(n.left);
  free_.push_back(n.right);
}

void KdTreeNearestNeighbors::rebuild(std::uint32_t root) {
  std::vector<Entry> entries;
  entries.reserve(nodes_[root].count);
  collect(root, entries);
  if (root == 0) {
    // The whole tree: into fresh slots, so that nodes are laid out depth-first.
    nodes_.assign(1, Node{});
    free_.clear();
  } else {
    nodes_[root] = Node{};
  }
  build(root, entries.begin(), entries.end());
}

void KdTreeNearestNeighbors::build(std::uint32_t node, std::vector<Entry>::iterator first,
                                   std::vector<Entry>::iterator last) {
  const auto count = static_cast<std::size_t>(last - first);
  Key lo = Key::Constant(std::numeric_limits<double>::infinity());
  Key hi = -lo;
  for (auto it = first; it != last; ++it) {
    lo = lo.cwiseMin(it->key);
    hi = hi.cwiseMax(it->key);
  }
  nodes_[node].count = static_cast<std::uint32_t>(count);
  nodes_[node].lo = lo;
  nodes_[node].hi = hi;
  int axis = 0;
  (hi - lo).cwiseProduct(axis_weights()).maxCoeff(&axis);
  if (count <= kBucketSize || !(hi[axis] > lo[axis])) {
    // A leaf (also when all points share one key: it then just grows).
    nodes_[node].axis = -1;
    nodes_[node].bucket.assign(first, last);
    return;
  }
  auto mid = first + static_cast<std::ptrdiff_t>(count / 2);
  std::nth_element(first, mid, last,
                   [&](const Entry& a, const Entry& b) { return a.key[axis] < b.key[axis]; });
  double split = mid->key[axis];
  if (split <= lo[axis])
    split = std::nextafter(lo[axis], hi[axis]);
  // Points at the split value go right; both sides are non-empty since lo < split <= hi.
  mid = std::partition(first, last, [&](const Entry& e) { return e.key[axis] < split; });
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
  std::vector<Entry> entries = std::move(nodes_[leaf].bucket);
  nodes_[leaf].bucket = {};
  build(leaf, entries.begin(), entries.end());
}

// A point is measured only when its lower bound does not exceed the current best.
template <class Visit>
void KdTreeNearestNeighbors::scan_leaf(const Node& leaf, const Query& query, Visit& visit) const {
  for (const Entry& e : leaf.bucket) {
    if (point_bound(query, e.key) > visit.bound())
      continue;
    visit.consider(e.id, space_.distance(query.q, points_[e.id]));
  }
}

// Depth-first, the child with the smaller bound first; a child is skipped when its bound exceeds
// the current best (equal may still hold a smaller id).
template <class Visit>
void KdTreeNearestNeighbors::search(std::uint32_t n, const Query& query, Visit& visit) const {
  const Node& node = nodes_[n];
  if (node.axis < 0) {
    scan_leaf(node, query, visit);
    return;
  }
  const Node& l = nodes_[node.left];
  const Node& r = nodes_[node.right];
  const double dl = box_bound(query, l.lo, l.hi);
  const double dr = box_bound(query, r.lo, r.hi);
  const bool left_first = dl <= dr;
  if ((left_first ? dl : dr) <= visit.bound())
    search(left_first ? node.left : node.right, query, visit);
  if ((left_first ? dr : dl) <= visit.bound())
    search(left_first ? node.right : node.left, query, visit);
}

KdTreeNearestNeighbors::Query KdTreeNearestNeighbors::query(const Config& q) const {
  const Key k = key(q);
  return Query{q, k, -k.tail<4>()};
}

NodeId KdTreeNearestNeighbors::nearest(const Config& q) const {
  if (size_ == 0)
    throw std::logic_error("nearest() on an empty index");
  struct Best {
    double d = std::numeric_limits<double>::infinity();
    NodeId id = 0;
    double bound() const { return d; }
    void consider(NodeId i, double di) {
      if (di < d || (di == d && i < id)) {
        d = di;
        id = i;
      }
    }
  } best;
  search(0, query(q), best);
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
      } else if (std::pair(di, i) < heap.top()) {
        heap.pop();
        heap.emplace(di, i);
      }
    }
  } best{k, {}};
  search(0, query(q), best);
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
