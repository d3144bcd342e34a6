#include "tandem/collision/mesh_proximity.hpp"

#include <fcl/narrowphase/detail/primitive_shape_algorithm/triangle_distance.h>

#include <algorithm>

namespace tandem {
namespace {

/// Head-room for the rounding of the boxes' and the triangles' arithmetic: the search starts a
/// hair beyond the cap, so that a pair at the cap, rounded up, is still searched.
constexpr double kRoundingShare = 1e-9;

/// One query: mesh b's frame in mesh a's (R, T), and the best distance found so far.
class Search {
 public:
  Search(const fcl::BVHModel<fcl::OBBd>& a, const fcl::BVHModel<fcl::OBBd>& b,
         const Eigen::Isometry3d& X_AB, double start, double relative_error)
      : a_(a),
        b_(b),
        R_(X_AB.linear()),
        T_(X_AB.translation()),
        shrink_(1.0 / (1.0 + relative_error)),
        best_(start) {}

  /// Lowers best to the distance of each pair of triangles under boxes i (of a) and j (of b)
  /// nearer than it, skipping the pairs of boxes farther apart than best / (1 + e); stops at an
  /// intersection. As FCL: the larger box is opened, or the one that is not a leaf.
  void search(int i, int j) {
    const fcl::BVNode<fcl::OBBd>& na = a_.getBV(i);
    const fcl::BVNode<fcl::OBBd>& nb = b_.getBV(j);
    if (best_ <= 0.0 || !boxes_within(na.bv, nb.bv, best_ * shrink_))
      return;
    const bool leaf_a = na.isLeaf();
    const bool leaf_b = nb.isLeaf();
    if (leaf_a && leaf_b) {
      best_ = std::min(best_, triangle_distance(na.primitiveId(), nb.primitiveId()));
    } else if (leaf_b || (!leaf_a && na.bv.size() > nb.bv.size())) {
      search(na.leftChild(), j);
      search(na.rightChild(), j);
    } else {
      search(i, nb.leftChild());
      search(i, nb.rightChild());
    }
  }

  double best() const { return best_; }

 private:
  /// fcl::overlap(R, T, ba, bb) with ba's half extents grown by d.
  bool boxes_within(const fcl::OBBd& ba, const fcl::OBBd& bb, double d) const {
    const Eigen::Matrix3d B = ba.axis.transpose() * (R_ * bb.axis);
    const Eigen::Vector3d T = ba.axis.transpose() * (R_ * bb.To + T_ - ba.To);
    return !fcl::obbDisjoint(B, T, Eigen::Vector3d(ba.extent.array() + d), bb.extent);
  }

  double triangle_distance(int ta, int tb) const {
    const fcl::Triangle& s = a_.tri_indices[ta];
    const fcl::Triangle& t = b_.tri_indices[tb];
    const Eigen::Vector3d P[3] = {a_.vertices[s[0]], a_.vertices[s[1]], a_.vertices[s[2]]};
    const Eigen::Vector3d Q[3] = {b_.vertices[t[0]], b_.vertices[t[1]], b_.vertices[t[2]]};
    Eigen::Vector3d p;
    Eigen::Vector3d q;
    return fcl::detail::TriangleDistance<double>::triDistance(P, Q, R_, T_, p, q);
  }

  const fcl::BVHModel<fcl::OBBd>& a_;
  const fcl::BVHModel<fcl::OBBd>& b_;
  const Eigen::Matrix3d R_;
  const Eigen::Vector3d T_;
  const double shrink_;
  double best_;
};

}  // namespace

double mesh_distance_bound(const fcl::BVHModel<fcl::OBBd>& a, const Eigen::Isometry3d& X_WA,
                           const fcl::BVHModel<fcl::OBBd>& b, const Eigen::Isometry3d& X_WB,
                           double cap, double relative_error) {
  const double grow = 1.0 + relative_error;
  Search s(a, b, X_WA.inverse() * X_WB, cap * grow * (1.0 + kRoundingShare), relative_error);
  s.search(0, 0);
  return std::min(cap, s.best() / grow);
}

}  // namespace tandem
