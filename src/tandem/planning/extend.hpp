#pragma once
// EXTEND (Kuffner & LaValle 2000): grow a tree from the node nearest to a target toward it, by at
// most `range`.

#include "tandem/collision/motion_validator.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/planning/tree.hpp"

namespace tandem {

enum class ExtendStatus : std::uint8_t {
  trapped,   ///< nothing added (the I-RRT's "Collision")
  advanced,  ///< a node was added one full range toward the target
  reached,   ///< a node equal to the target was added (the I-RRT's "Reached")
  stopped,   ///< last_valid mode: a node was added short of the target, at an obstacle ("Obstacle")
};

struct Extension {
  ExtendStatus status = ExtendStatus::trapped;
  NodeId node = 0;  ///< the node added (valid unless trapped)
  NodeId near = 0;  ///< q_near, the node extended from
};

/// q_near <- nearest(T, q_target); q_new <- q_target if within range, else the point at `range`
/// toward it; then the motion q_near -> q_new is validated as `mode` says and q_new (or the last
/// valid configuration) is added with q_near as parent.
Extension extend(Tree& tree, const Config& q_target, double range, MotionValidator& validator,
                 ExtendMode mode, NodeSource source = NodeSource::random);

}  // namespace tandem
