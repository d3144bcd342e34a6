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

#include "tandem/core/rng.hpp"
#include "tandem/interaction/contact_frame.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

/// A contact sample, or nothing if the plane misses the bounds.
std::optional<Config> sample_contact(const ContactFrame& frame,
                                     const Eigen::Quaterniond& q_operator, const SE3Space& space,
                                     double clearance, Rng& rng);

}  // namespace tandem
