#include "tandem/operators/guide_follower.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace tandem {

GuideFollower::GuideFollower(const SE3Space& space, std::vector<Config> keyframes,
                             OperatorProfile profile, std::uint64_t seed)
    : space_(space), keyframes_(std::move(keyframes)), profile_(std::move(profile)) {
  if (keyframes_.empty())
    throw std::invalid_argument("a guide needs at least one keyframe");
  if (!(profile_.speed > 0.0))
    throw std::invalid_argument("the operator's speed must be positive");
  cumulative_.push_back(0.0);
  for (std::size_t i = 1; i < keyframes_.size(); ++i) {
    cumulative_.push_back(cumulative_.back() + space_.distance(keyframes_[i - 1], keyframes_[i]));
  }
  Rng rng(seed);

  // s(t): move forward at the profile's speed; at pauses (a Poisson process along the guide) maybe
  // back up first, then stand still.
  const double length = guide_length();
  const double v = profile_.speed;
  timeline_.push_back({0.0, 0.0});
  double s = 0.0, t = 0.0;
  auto next_pause = [&] {
    return profile_.pause_rate > 0.0 ? -std::log(1.0 - rng.uniform01()) / profile_.pause_rate
                                     : std::numeric_limits<double>::infinity();
  };
  double pause_at = next_pause();
  while (s < length) {
    if (pause_at >= length) {
      t += (length - s) / v;
      s = length;
      timeline_.push_back({t, s});
      break;
    }
    t += (pause_at - s) / v;
    s = pause_at;
    timeline_.push_back({t, s});
    if (rng.uniform01() < profile_.backtrack_share) {
      const double back = std::min(profile_.backtrack_distance, s);
      t += back / v;
      s -= back;
      timeline_.push_back({t, s});
    }
    t += profile_.pause_duration;
    timeline_.push_back({t, s});
    pause_at = std::max(pause_at, s) + next_pause();
  }
  if (timeline_.size() == 1)
    timeline_.push_back({0.0, 0.0});

  // Tremor: per channel, a few sinusoids around the profile's frequency, with random phases.
  constexpr int kWaves = 4;
  tremor_.resize(6);
  for (int c = 0; c < 6; ++c) {
    const double amplitude =
        (c < 3 ? profile_.tremor_translation : profile_.tremor_rotation) / std::sqrt(kWaves);
    for (int w = 0; w < kWaves; ++w) {
      tremor_[static_cast<std::size_t>(c)].push_back(
          {profile_.tremor_frequency * rng.uniform(0.6, 1.4),
           rng.uniform(0.0, 2.0 * std::numbers::pi), amplitude});
    }
  }
}

double GuideFollower::progress(double t) const {
  if (t <= timeline_.front().t)
    return timeline_.front().s;
  if (t >= timeline_.back().t)
    return timeline_.back().s;
  auto it = std::upper_bound(timeline_.begin(), timeline_.end(), t,
                             [](double x, const Breakpoint& b) { return x < b.t; });
  const Breakpoint& b = *it;
  const Breakpoint& a = *(it - 1);
  if (b.t <= a.t)
    return b.s;
  return a.s + (b.s - a.s) * (t - a.t) / (b.t - a.t);
}

Config GuideFollower::guide_pose(double s) const {
  s = std::clamp(s, 0.0, guide_length());
  auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  if (it == cumulative_.end())
    return keyframes_.back();
  const auto i = static_cast<std::size_t>(it - cumulative_.begin());
  const double span = cumulative_[i] - cumulative_[i - 1];
  return space_.interpolate(keyframes_[i - 1], keyframes_[i],
                            span > 0.0 ? (s - cumulative_[i - 1]) / span : 0.0);
}

Config GuideFollower::pose(double t, double pace) const {
  Config q = guide_pose(progress(pace));
  Eigen::Matrix<double, 6, 1> noise;
  for (std::size_t c = 0; c < 6; ++c) {
    double x = 0.0;
    for (const Wave& w : tremor_[c])
      x += w.amplitude * std::sin(2.0 * std::numbers::pi * w.frequency * t + w.phase);
    noise[static_cast<Eigen::Index>(c)] = x;
  }
  if (space_.planar()) {
    noise[2] = noise[3] = noise[4] = 0.0;
  }
  q.t += noise.head<3>();
  const Eigen::Vector3d rv = noise.tail<3>();
  if (rv.norm() > 0.0)
    q.q = (Eigen::Quaterniond(Eigen::AngleAxisd(rv.norm(), rv.normalized())) * q.q).normalized();
  // A person cannot take the object outside the workspace.
  q.t = q.t.cwiseMax(space_.bounds().min).cwiseMin(space_.bounds().max);
  return q;
}

DeviceReading GuideFollower::read_paced(double t, double pace) const {
  DeviceReading r;
  r.q_device = pose(t, pace);
  // Velocity by a central difference over a tenth of the tremor's period (or of a time unit), as if
  // the pace kept up with the time around t.
  const double h = profile_.tremor_frequency > 0.0 ? 0.1 / profile_.tremor_frequency : 0.1;
  const double before = std::min(h, std::min(t, pace));
  const Config a = pose(t - before, pace - before), b = pose(t + h, pace + h);
  const double dt = h + before;
  r.velocity.head<3>() = (b.t - a.t) / dt;
  Eigen::Quaterniond dq = b.q * a.q.inverse();
  if (dq.w() < 0.0)
    dq.coeffs() = -dq.coeffs();
  const Eigen::AngleAxisd aa(dq);
  r.velocity.tail<3>() = aa.axis() * aa.angle() / dt;
  return r;
}

std::string GuideFollower::describe() const {
  std::ostringstream os;
  os << profile_.name << " operator following a guide of " << keyframes_.size()
     << " keyframes (length " << guide_length() << ", speed " << profile_.speed << " per time unit";
  if (std::isfinite(profile_.lead))
    os << ", at most " << profile_.lead << " ahead of the roadmap";
  os << ")";
  return os.str();
}

}  // namespace tandem
