#include "tandem/planning/irrt.hpp"

#include <stdexcept>

#include "tandem/planning/extend.hpp"
#include "tandem/sampling/gaussian_shooter.hpp"

namespace tandem {
namespace {

constexpr std::size_t kPathLength = 200;   ///< user positions kept for PATH sampling
constexpr std::size_t kMotionWindow = 20;  ///< user positions over which F_u is measured

}  // namespace

IRRT::IRRT(MotionValidator& validator, const Config& start, const Config& goal,
           const PlannerSettings& settings, const Interaction& interaction)
    : Planner(validator, start, goal, settings),
      interaction_(interaction),
      tree_(validator.space(), settings.nearest_neighbors, start),
      shot_rng_(settings.seed ^ 0x3c3c3c3c9e3779b9ULL) {
  if (interaction.feed == nullptr)
    throw std::invalid_argument("the I-RRT needs an operator (an OperatorFeed)");
  attach(tree_);
  labels_.push_back({space_.distance(start, goal)});
}

void IRRT::update_user(const OperatorState& op) {
  if (op.sequence == last_sequence_)
    return;
  last_sequence_ = op.sequence;
  user_path_.push_back(op.device.q_device);
  if (user_path_.size() > kPathLength)
    user_path_.pop_front();
}

void IRRT::update_forces(const Config& q_user, const InteractionSettings& s) {
  // F_u: how the user moved lately.
  const std::size_t n = user_path_.size();
  f_u_ = n > 1
             ? tangent_difference(user_path_[n - std::min(n, kMotionWindow + 1)], user_path_.back())
             : Twist::Zero();
  // F_a: toward the labelled centre of mass of the p nearest nodes.
  tree_.nn->k_nearest(q_user, static_cast<std::size_t>(std::max(1, s.neighbours)), near_);
  const double floor = space_.max_extent() / 100.0;
  double total = 0.0;
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Vector4d q = Eigen::Vector4d::Zero();
  for (NodeId id : near_) {
    const NodeLabel& l = labels_[id];
    const double w = (1.0 - l.collision_label) / (l.distance_to_goal + floor);
    const Config& c = tree_.nodes[id];
    t += w * c.t;
    Eigen::Vector4d v = c.q.coeffs();
    if (v.dot(q_user.q.coeffs()) < 0.0)
      v = -v;  // average on q_user's hemisphere
    q += w * v;
    total += w;
  }
  Config com = q_user;
  if (total > 0.0 && q.norm() > 0.0) {
    com.t = t / total;
    q.normalize();
    com.q = Eigen::Quaterniond(q[3], q[0], q[1], q[2]);
  }
  f_a_ = tangent_difference(q_user, com);
  f_r_ = s.force_mix * f_u_ + (1.0 - s.force_mix) * f_a_;
  if (interaction_.guidance != nullptr)
    interaction_.guidance->publish({stats().iterations, f_a_});
}

Config IRRT::shoot(const Config& q_user, const InteractionSettings& s, NodeSource& source,
                   bool& toward_goal) {
  toward_goal = rng_.uniform01() < settings_.goal_bias;
  source = NodeSource::random;
  if (toward_goal)
    return goal_;
  const double sigma_t = sigma_translation(s, space_);
  const double sigma_r = sigma_t / space_.translation_extent() * std::numbers::pi;
  if (s.sampling == IrrtSampling::mag_cs || s.sampling == IrrtSampling::path_cs) {
    // One uniform shot every x, x growing with the user's motion (in units of sigma).
    const double motion = f_u_.head<3>().norm() / sigma_t + f_u_.tail<3>().norm() / sigma_r;
    const auto x = static_cast<std::uint64_t>(std::max(1.0, s.uniform_every * (1.0 + motion)));
    if (++shots_since_uniform_ >= x) {
      shots_since_uniform_ = 0;
      return space_.sample_uniform(rng_);
    }
  }
  const bool path_mode = s.sampling == IrrtSampling::path || s.sampling == IrrtSampling::path_cs;
  const Config& centre =
      path_mode && !user_path_.empty() ? user_path_[shot_rng_.below(user_path_.size())] : q_user;
  source = NodeSource::operator_;
  return gaussian_shot(space_, centre, f_r_, sigma_t, sigma_r, shot_rng_);
}

SamplerStats IRRT::sampler_stats() const {
  return {interaction_.feed->operator_seconds(), operator_iterations_, 0};
}

void IRRT::update_labels(const Extension& e) {
  if (e.added) {
    labels_.push_back({space_.distance(tree_.nodes[e.node], goal_)});
  }
  NodeLabel& near = labels_[e.near];  // after the push_back, which may move the labels
  ++near.extensions;
  if (e.status == ExtendStatus::trapped) {
    ++near.collisions;
  } else {
    near.covered += space_.distance(tree_.nodes[e.near], tree_.nodes[e.node]);
  }
  near.collision_label = static_cast<double>(near.collisions) / (near.extensions + 1.0) *
                         std::max(0.0, 1.0 - near.covered / (near.extensions * range_));
}

bool IRRT::iterate() {
  const InteractionSettings& s = interaction_.parameters != nullptr
                                     ? interaction_.parameters->latest()
                                     : settings_.interaction;
  const OperatorState* op = interaction_.feed->at(stats().iterations, this);
  NodeSource source = NodeSource::random;
  bool toward_goal = false;
  Config q_rand;
  if (op == nullptr) {
    q_rand = space_.sample_uniform(rng_);
  } else {
    ++operator_iterations_;
    update_user(*op);
    update_forces(op->device.q_device, s);
    q_rand = shoot(op->device.q_device, s, source, toward_goal);
  }
  // 4. EXTEND.
  const Extension e = extend(tree_, q_rand, range_, validator_, settings_.extend, source);
  count_extension(e.status);
  update_labels(e);
  if (!(toward_goal && e.status == ExtendStatus::reached))
    return false;
  solution_ = tree_.path_from_root(e.node);
  return true;
}

}  // namespace tandem
