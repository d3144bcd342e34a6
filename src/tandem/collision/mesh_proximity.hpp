#pragma once
// A lower bound on the distance between two meshes, capped: the search FCL's fcl::distance makes
// over a pair of bounding-volume trees, made over the oriented-box (OBB) trees FCL builds for
// yes/no collision, with each box grown by the distance searched for.
//
// A box grown by d along each of its axes holds every point within d of the box, so a pair of
// boxes that the separating-axis test finds apart once one is grown by d holds no pair of points
// within d. The search opens every pair of boxes that may hold triangles nearer than the best
// distance found so far (at first the cap) and lowers it with the exact distance of each pair of
// triangles (FCL's). Beside fcl::distance on OBBRSS trees, which computes a distance between
// rectangle-swept spheres for every pair of boxes it meets, a separating-axis test is a few dozen
// operations: on Apartment's near-contact states a query capped at a quarter resolution step
// took 47 us against FCL's 103 (bench/check_costs.cpp).
//
// Threading: a pure function of immutable models; safe to call from any thread.

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBB.h>

#include <Eigen/Geometry>

namespace tandem {

/// A lower bound on the distance between mesh a posed at X_WA and mesh b posed at X_WB, capped:
/// min(cap, d / (1 + relative_error)), where d is the least distance between the pairs of
/// triangles searched and the search skips every pair of boxes farther apart than the best d so
/// far divided by 1 + relative_error. It is cap when nothing is nearer than cap, and 0 when the
/// meshes intersect.
double mesh_distance_bound(const fcl::BVHModel<fcl::OBBd>& a, const Eigen::Isometry3d& X_WA,
                           const fcl::BVHModel<fcl::OBBd>& b, const Eigen::Isometry3d& X_WB,
                           double cap, double relative_error);

}  // namespace tandem
