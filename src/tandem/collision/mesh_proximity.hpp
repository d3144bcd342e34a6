#pragma once
// Yes/no collision and capped distance bounds between two meshes, by the searches FCL's
// fcl::collide and fcl::distance make over a pair of bounding-volume trees, made here over the
// oriented-box (OBB) trees FCL builds.
//
// Collision: the same boxes tested the same way and FCL's own test of a pair of triangles, so the
// answer is fcl::collide's; of the two children of an opened box, the one nearer the other box
// goes first, and a colliding query meets an intersecting pair sooner. Without FCL's dispatch and
// result objects, and with that order, a query on Apartment's (mostly colliding) uniform states
// took 19 us against fcl::collide's 34 (bench/check_costs.cpp, "collide").
//
// Distance: a box grown by d along each of its axes holds every point within d of the box, so a
// pair of boxes that the separating-axis test finds apart once one is grown by d holds no pair of
// points within d. The search opens every pair of boxes that may hold triangles nearer than the
// best distance found so far (at first the cap) and lowers it with the exact distance of each
// pair of triangles (FCL's). Beside fcl::distance on OBBRSS trees, which computes a distance
// between rectangle-swept spheres for every pair of boxes it meets, a separating-axis test is a
// few dozen operations: on Apartment's near-contact states a clearance query capped at one
// resolution step took 127 us against 211 ("clearance").
//
// Both add the pairs they tested to `tests` when given (the portfolio's measure of a search's
// work, runs/portfolio.hpp).
//
// Threading: pure functions of immutable models; safe to call from any thread.

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBB.h>

#include <Eigen/Geometry>
#include <cstdint>

namespace tandem {

/// The pairs of boxes and of triangles a walk tested: a measure of its work that depends only on
/// the query (the same on every machine), not on the clock.
struct WalkTests {
  std::uint64_t boxes = 0;
  std::uint64_t triangles = 0;
};

/// Whether mesh a posed at X_WA and mesh b posed at X_WB intersect, as fcl::collide answers.
bool meshes_intersect(const fcl::BVHModel<fcl::OBBd>& a, const Eigen::Isometry3d& X_WA,
                      const fcl::BVHModel<fcl::OBBd>& b, const Eigen::Isometry3d& X_WB,
                      WalkTests* tests = nullptr);

/// A lower bound on the distance between mesh a posed at X_WA and mesh b posed at X_WB, capped:
/// min(cap, d / (1 + relative_error)), where d is the least distance between the pairs of
/// triangles searched and the search skips every pair of boxes farther apart than the best d so
/// far divided by 1 + relative_error. It is cap when nothing is nearer than cap, and 0 when the
/// meshes intersect.
double mesh_distance_bound(const fcl::BVHModel<fcl::OBBd>& a, const Eigen::Isometry3d& X_WA,
                           const fcl::BVHModel<fcl::OBBd>& b, const Eigen::Isometry3d& X_WB,
                           double cap, double relative_error, WalkTests* tests = nullptr);

}  // namespace tandem
