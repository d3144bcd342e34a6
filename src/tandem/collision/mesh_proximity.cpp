#include "tandem/collision/mesh_proximity.hpp"

#include <fcl/math/geometry.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/triangle_distance.h>
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>

#include <algorithm>
#include <utility>

#include "tandem/collision/box_separation.hpp"

namespace tandem {
namespace {

using ObbTree = fcl::BVHModel<fcl::OBBd>;

/// Head-room for the rounding of the boxes' and the triangles' arithmetic: the distance search
/// starts a hair beyond the cap, so that a pair at the cap, rounded up, is still searched.
constexpr double kRoundingShare = 1e-9;

/// fcl::BVNodeBase's isLeaf(), primitiveId(), leftChild() and rightChild(), which libfcl
/// compiles out of line: read here from first_child as FCL defines them, inline in the walk.
bool is_leaf(const fcl::BVNodeBase& n) {
  return n.first_child < 0;
}
int primitive_of(const fcl::BVNodeBase& n) {
  return -(n.first_child + 1);
}
int left_of(const fcl::BVNodeBase& n) {
  return n.first_child;
}
int right_of(const fcl::BVNodeBase& n) {
  return n.first_child + 1;
}

/// A·B of 3×3 matrices by dot products: a box's placement is the walk's hottest arithmetic after
/// the box test, and Eigen's product of two matrices is a call at -O2.
Eigen::Matrix3d product(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  Eigen::Matrix3d C;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      C(r, c) = A.row(r).dot(B.col(c));
  }
  return C;
}

/// Two trees and mesh b's frame in mesh a's (R, T, as fcl::collide computes them), walked as FCL
/// walks them: of a pair of boxes, the larger is opened, or the one that is not a leaf.
class TreePair {
 public:
  TreePair(const ObbTree& a, const Eigen::Isometry3d& X_WA, const ObbTree& b,
           const Eigen::Isometry3d& X_WB, WalkTests& tests)
      : a_(a), b_(b), tests_(tests) {
    fcl::relativeTransform(X_WA.linear(), X_WA.translation(), X_WB.linear(), X_WB.translation(), R_,
                           T_);
  }

  /// Box j of b in a's frame: its axes and centre. A walk that opens a's boxes against box j
  /// places it once.
  struct Placed {
    Eigen::Matrix3d axis;
    Eigen::Vector3d center;
  };

  Placed place(int j) const {
    const fcl::OBBd& bb = b_.getBV(j).bv;
    return {product(R_, bb.axis), R_ * bb.To + T_};
  }

  /// Whether a pair of triangles under boxes i (of a) and j (of b, placed as pb) intersects:
  /// FCL's test of a pair of triangles, so the answer is fcl::collide's. The children nearer the
  /// other box (by their centres) first: a colliding query stops sooner.
  bool intersect(int i, int j, const Placed& pb) const {
    const fcl::BVNode<fcl::OBBd>& na = a_.getBV(i);
    const fcl::BVNode<fcl::OBBd>& nb = b_.getBV(j);
    ++tests_.boxes;
    if (!boxes_within(na.bv, pb, nb.bv.extent, 0.0))
      return false;
    if (is_leaf(na) && is_leaf(nb))
      return triangles_intersect(primitive_of(na), primitive_of(nb));
    if (open_a(na, nb)) {
      const auto [first, second] = nearer_first(a_, na, pb.center);
      return intersect(first, j, pb) || intersect(second, j, pb);
    }
    const auto [first, second] = nearer_first(b_, nb, R_.transpose() * (na.bv.To - T_));
    return intersect(i, first, place(first)) || intersect(i, second, place(second));
  }

  /// Lowers best to the distance of each pair of triangles under boxes i and j (placed as pb)
  /// nearer than it, skipping the pairs of boxes farther apart than best * shrink; stops at an
  /// intersection.
  void lower(int i, int j, const Placed& pb, double shrink, double& best) const {
    const fcl::BVNode<fcl::OBBd>& na = a_.getBV(i);
    const fcl::BVNode<fcl::OBBd>& nb = b_.getBV(j);
    if (best <= 0.0)
      return;
    ++tests_.boxes;
    if (!boxes_within(na.bv, pb, nb.bv.extent, best * shrink))
      return;
    if (is_leaf(na) && is_leaf(nb)) {
      best = std::min(best, triangle_distance(primitive_of(na), primitive_of(nb)));
    } else if (open_a(na, nb)) {
      lower(left_of(na), j, pb, shrink, best);
      lower(right_of(na), j, pb, shrink, best);
    } else {
      lower(i, left_of(nb), place(left_of(nb)), shrink, best);
      lower(i, right_of(nb), place(right_of(nb)), shrink, best);
    }
  }

 private:
  static bool open_a(const fcl::BVNode<fcl::OBBd>& na, const fcl::BVNode<fcl::OBBd>& nb) {
    return is_leaf(nb) || (!is_leaf(na) && na.bv.extent.squaredNorm() > nb.bv.extent.squaredNorm());
  }

  /// The children of node n of tree t, the one whose centre is nearer c (in t's frame) first.
  static std::pair<int, int> nearer_first(const ObbTree& t, const fcl::BVNode<fcl::OBBd>& n,
                                          const Eigen::Vector3d& c) {
    const int left = left_of(n);
    const int right = right_of(n);
    const bool swap =
        (t.getBV(right).bv.To - c).squaredNorm() < (t.getBV(left).bv.To - c).squaredNorm();
    return swap ? std::pair{right, left} : std::pair{left, right};
  }

  /// fcl::overlap(R, T, ba, bb) with ba's half extents grown by d, for a box bb placed as pb
  /// with half extents extent_b: false only when no point of bb is within d of ba.
  static bool boxes_within(const fcl::OBBd& ba, const Placed& pb, const Eigen::Vector3d& extent_b,
                           double d) {
    return !boxes_apart(ba.axis, pb.center - ba.To, Eigen::Vector3d(ba.extent.array() + d), pb.axis,
                        extent_b);
  }

  bool triangles_intersect(int ta, int tb) const {
    ++tests_.triangles;
    const fcl::Triangle& s = a_.tri_indices[ta];
    const fcl::Triangle& t = b_.tri_indices[tb];
    return fcl::detail::Intersect<double>::intersect_Triangle(
        a_.vertices[s[0]], a_.vertices[s[1]], a_.vertices[s[2]], b_.vertices[t[0]],
        b_.vertices[t[1]], b_.vertices[t[2]], R_, T_);
  }

  double triangle_distance(int ta, int tb) const {
    ++tests_.triangles;
    const fcl::Triangle& s = a_.tri_indices[ta];
    const fcl::Triangle& t = b_.tri_indices[tb];
    const Eigen::Vector3d P[3] = {a_.vertices[s[0]], a_.vertices[s[1]], a_.vertices[s[2]]};
    const Eigen::Vector3d Q[3] = {b_.vertices[t[0]], b_.vertices[t[1]], b_.vertices[t[2]]};
    Eigen::Vector3d p;
    Eigen::Vector3d q;
    return fcl::detail::TriangleDistance<double>::triDistance(P, Q, R_, T_, p, q);
  }

  const ObbTree& a_;
  const ObbTree& b_;
  WalkTests& tests_;
  Eigen::Matrix3d R_;
  Eigen::Vector3d T_;
};

}  // namespace

bool meshes_intersect(const ObbTree& a, const Eigen::Isometry3d& X_WA, const ObbTree& b,
                      const Eigen::Isometry3d& X_WB, WalkTests* tests) {
  WalkTests here;
  const TreePair pair(a, X_WA, b, X_WB, tests != nullptr ? *tests : here);
  return pair.intersect(0, 0, pair.place(0));
}

double mesh_distance_bound(const ObbTree& a, const Eigen::Isometry3d& X_WA, const ObbTree& b,
                           const Eigen::Isometry3d& X_WB, double cap, double relative_error,
                           WalkTests* tests) {
  const double grow = 1.0 + relative_error;
  double best = cap * grow * (1.0 + kRoundingShare);
  WalkTests here;
  const TreePair pair(a, X_WA, b, X_WB, tests != nullptr ? *tests : here);
  pair.lower(0, 0, pair.place(0), 1.0 / grow, best);
  return std::min(cap, best / grow);
}

}  // namespace tandem
