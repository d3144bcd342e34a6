#pragma once
// EXTEND (Kuffner & LaValle 2000): grow a tree from the node nearest to a target toward it, by at
// most `range`.

#include "tandem/collision/motion_validator.hpp"
#include "tandem/planning/extend_status.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/planning/tree.hpp"

namespace tandem {

class AdaptiveStep;

struct Extension {
  ExtendStatus status = ExtendStatus::trapped;
  NodeId node = 0;     ///< the node added, or q_near when it is the target (valid unless trapped)
  NodeId near = 0;     ///< q_near, the node extended from
  bool added = false;  ///< a node was added (not when the target was a node already)
};

/// q_near <- nearest(T, q_target); q_new <- q_target if within range, else the point at `range`
/// toward it; then the motion q_near -> q_new is validated as `mode` says and q_new (or the last
/// valid configuration) is added with q_near as parent. A target that is a node already is reached
/// with nothing added. With `steps`, the range is q_near's step, and the outcome updates them.
Extension extend(Tree& tree, const Config& q_target, double range, MotionValidator& validator,
                 ExtendMode mode, NodeSource source = NodeSource::random,
                 AdaptiveStep* steps = nullptr);

}  // namespace tandem
