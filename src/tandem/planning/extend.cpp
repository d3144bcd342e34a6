#include "tandem/planning/extend.hpp"

namespace tandem {

Extension extend(Tree& tree, const Config& q_target, double range, MotionValidator& validator,
                 ExtendMode mode, NodeSource source) {
  const SE3Space& space = validator.space();
  Extension e;
  e.near = tree.nearest(q_target);
  const Config& q_near = tree.nodes[e.near];
  const double d = space.distance(q_near, q_target);
  const bool within = d <= range;
  const Config q_new = within ? q_target : space.interpolate(q_near, q_target, range / d);

  if (mode == ExtendMode::classic) {
    if (!validator.check_motion(q_near, q_new))
      return e;
    e.node = tree.add(q_new, e.near, source);
    e.status = within ? ExtendStatus::reached : ExtendStatus::advanced;
    return e;
  }
  MotionCheck check = validator.check_motion_last_valid(q_near, q_new);
  if (check.valid) {
    e.node = tree.add(q_new, e.near, source);
    e.status = within ? ExtendStatus::reached : ExtendStatus::advanced;
  } else if (check.last_valid_step > 0) {
    e.node = tree.add(check.last_valid, e.near, source);
    e.status = ExtendStatus::stopped;
  }
  return e;
}

}  // namespace tandem
