#include "tandem/planning/extend.hpp"

#include "tandem/planning/adaptive_step.hpp"

namespace tandem {
namespace {

/// The motion from e.near toward q_target (at distance d), validated as `mode` says.
Extension extend_checked(Tree& tree, Extension e, double d, const Config& q_target, double range,
                         MotionValidator& validator, ExtendMode mode, NodeSource source) {
  const SE3Space& space = validator.space();
  const Config& q_near = tree.nodes[e.near];
  const bool within = d <= range;
  const Config q_new = within ? q_target : space.interpolate(q_near, q_target, range / d);

  if (mode == ExtendMode::classic) {
    if (!validator.check_motion(q_near, q_new))
      return e;
    e.node = tree.add(q_new, e.near, source);
    e.added = true;
    e.status = within ? ExtendStatus::reached : ExtendStatus::advanced;
    return e;
  }
  MotionCheck check = validator.check_motion_last_valid(q_near, q_new);
  if (check.valid) {
    e.node = tree.add(q_new, e.near, source);
    e.added = true;
    e.status = within ? ExtendStatus::reached : ExtendStatus::advanced;
  } else if (check.last_valid_step > 0) {
    e.node = tree.add(check.last_valid, e.near, source);
    e.added = true;
    e.status = ExtendStatus::stopped;
  }
  return e;
}

}  // namespace

Extension extend(Tree& tree, const Config& q_target, double range, MotionValidator& validator,
                 ExtendMode mode, NodeSource source, AdaptiveStep* steps) {
  Extension e;
  e.near = tree.nearest(q_target);
  const double d = validator.space().distance(tree.nodes[e.near], q_target);
  if (d == 0.0) {
    // The target is a node already (an operator holding the part still is the same target
    // iteration after iteration): reached, and nothing to add.
    e.status = ExtendStatus::reached;
    e.node = e.near;
    return e;
  }
  const double step = steps != nullptr ? steps->step(e.near) : range;
  e = extend_checked(tree, e, d, q_target, step, validator, mode, source);
  if (steps != nullptr) {
    if (e.status == ExtendStatus::trapped)
      steps->blocked(e.near);
    else if (e.added)
      steps->added(e.node, e.near);
  }
  return e;
}

}  // namespace tandem
