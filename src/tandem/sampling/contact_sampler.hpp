#pragma once
// Contact_Shooter of Blin et al., "I-RRT-C: Interactive Motion Planning with Contact" (IROS 2016),
// Algorithm 2, line 3.
//
// The orientation is the operator's (kept constant while in contact); the translation is drawn
// uniformly on the plane through P_c perpendicular to n, inside the workspace bounds, then moved
// along -n so that the object's nearest point comes to `clearance` above the obstacle's tangent
// plane at P_o. On that plane the object slides on the obstacle: for a flat face its distance to
// the obstacle is `clearance` wherever the face continues under it.
//
// FCL counts touching as collision, so contact samples keep a small clearance; tandem's default is
// 0.1 x the space's translation step (documented with the planner settings), far below what the
// motion checks resolve. In a planar space the plane is a line in the plane of motion.

#include <optional>
#include <vector>

#include "tandem/core/rng.hpp"
#include "tandem/interaction/contact_frame.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

/// A contact sample, or nothing if the plane misses the bounds.
std::optional<Config> sample_contact(const ContactFrame& frame,
                                     const Eigen::Quaterniond& q_operator, const SE3Space& space,
                                     double clearance, Rng& rng);

/// Beyond one plane (the 2016 paper's future work). The orientation: the operator's, turned about
/// the first frame's normal by an angle uniform in [-turn, turn] (radians) about the object's
/// nearest point, which keeps a flat face at its distance from its plane (with turn 0 and one
/// frame, exactly sample_contact). The translation: with
/// one frame, sample_contact's; with two (normals not parallel), uniform on the line where the
/// object is `clearance` above both tangent planes, inside the bounds (an edge); with three, the
/// point above all three (a corner). Nothing if the line or point misses the bounds.
std::optional<Config> sample_contact_surfaces(const std::vector<ContactFrame>& frames,
                                              const Eigen::Quaterniond& q_operator,
                                              const SE3Space& space, double clearance, double turn,
                                              Rng& rng);

/// Of frames (nearest first), those whose normals are at least 30 degrees from every one kept
/// before them, at most `most`: the distinct surfaces of an edge or a corner.
std::vector<ContactFrame> distinct_surfaces(const std::vector<ContactFrame>& frames,
                                            std::size_t most);

}  // namespace tandem
