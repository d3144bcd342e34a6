#pragma once
// A simulated operator that follows a guide: the 2011 paper's simulated user, "incrementing the
// user's position by a step epsilon along a predefined path" (section VII), with tremor and
// hesitation.
//
// The guide is a handful of keyframes placed by hand in the scene's file; it is coarse (it may pass
// through obstacles, as a person's rough gesture does) and knows nothing of any planner's output.
// The operator moves along the piecewise geodesic through the keyframes at the profile's speed;
// pauses and back-ups are drawn once, at construction, from the seed, so read(t) is a pure function
// of t.

#include <cstdint>
#include <vector>

#include "tandem/core/rng.hpp"
#include "tandem/interaction/operator_source.hpp"
#include "tandem/operators/operator_profile.hpp"

namespace tandem {

class GuideFollower final : public OperatorSource {
 public:
  /// Throws std::invalid_argument for fewer than one keyframe.
  GuideFollower(const SE3Space& space, std::vector<Config> keyframes, OperatorProfile profile,
                std::uint64_t seed);

  DeviceReading read(double t) const override { return read_paced(t, t); }
  /// Progress along the guide at time `pace`, tremor at time t.
  DeviceReading read_paced(double t, double pace) const override;
  double lead() const override { return profile_.lead; }
  double end_time() const override { return timeline_.back().t; }
  std::string describe() const override;

  /// The noiseless pose at distance s along the guide (clamped to [0, length]).
  Config guide_pose(double s) const;
  double guide_length() const { return cumulative_.back(); }
  /// Distance along the guide reached at time t (pauses and back-ups included).
  double progress(double t) const;

 private:
  struct Breakpoint {
    double t, s;
  };
  struct Wave {
    double frequency, phase, amplitude;
  };

  Config pose(double t, double pace) const;

  const SE3Space& space_;
  std::vector<Config> keyframes_;
  std::vector<double> cumulative_;  ///< arc length at each keyframe
  OperatorProfile profile_;
  std::vector<Breakpoint> timeline_;       ///< s(t), piecewise linear
  std::vector<std::vector<Wave>> tremor_;  ///< six channels: x, y, z, rx, ry, rz
};

}  // namespace tandem
